#pragma once
/// \file
/// \brief The environments and robots of the shipped planning problems (problems/*.cfg), made by
/// our own generator so that they can be shared (no OMPL.app meshes).
///
/// Every robot is returned centred on the mean of its vertices, the frame OMPL.app's convention
/// re-centres it to, so the poses in the .cfg files mean the same before and after loading.
/// Lengths in metres; SE(2) scenes are extruded: walls span z in [-1, 1] and the robots sit
/// around z = 0.

#include <string>
#include <vector>

#include "adsd/mesh.h"

namespace adsd::shapes {

/// \brief One problem's meshes; `name` is the file stem the cfg refers to (NAME_robot.obj,
/// NAME_env.obj). A scene whose robot comes from the real-model cache has no robot here.
struct ProblemScene {
  std::string name;
  std::vector<Mesh> robot;  ///< empty or one mesh
  Mesh environment;
};

/// SE(2): an office floor with two rows of cubicles and narrow doors (the default problem).
ProblemScene officeScene();
/// SE(2): a perfect 8 × 8 maze (fixed seed) extruded into walls; a small box robot.
ProblemScene mazeScene();
/// SE(2): a wall 2 cm thick with a gap at one end, and a bar robot 2 cm thick: OMPL's discrete
/// motion check steps over the wall, the certified one does not.
ProblemScene thinWallScene();
/// SE(3): a closed box with a square funnel leading inwards; a rod robot starts inside.
ProblemScene bugTrapScene();
/// SE(3): a square tunnel crossed by three plates whose slots turn by 60° each; a flat bar robot.
ProblemScene twistedPassageScene();
/// SE(3): two interlocked alpha-like tubes (a one-turn helical loop with crossing tails); the
/// robot is the second tube and must be threaded out through the gap between the first's tails.
ProblemScene alphaPuzzleScene();
/// SE(3): two rooms joined by a window too narrow for a cow walking upright (robot: the CGAL cow
/// from the real-model cache, problems/data/fetch_meshes.sh).
ProblemScene cowDoorwayScene();

/// \brief All of the above, in a stable order.
std::vector<ProblemScene> allProblemScenes();

/// \brief A closed tube of radius \p radius swept along the polyline \p centreLine (capped at both
/// ends), with \p sides vertices around each ring. Frames are carried along by parallel transport
/// so the tube does not twist.
Mesh sweptTube(const std::vector<Vec3>& centreLine, double radius, int sides);

/// \brief \p mesh moved so that the mean of its vertices is the origin.
Mesh centredOnVertexMean(const Mesh& mesh);

/// \brief Writes \p mesh as a Wavefront OBJ (vertices, then 1-based triangles) through a temporary
/// file renamed on success; throws adsd::InputError naming the file on failure.
void writeObj(const Mesh& mesh, const std::string& path);

}  // namespace adsd::shapes
