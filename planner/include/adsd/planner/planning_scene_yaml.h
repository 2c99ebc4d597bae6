#pragma once
/// \file
/// \brief MoveIt PlanningScene YAML files (MotionBenchMaker's scene0001.yaml) read into meshes in
/// the world frame.
///
/// What is read (moveit_msgs/PlanningScene, CollisionObject, shape_msgs/SolidPrimitive and Mesh;
/// docs/problem-files.md lists it with what is ignored):
///   name                                   optional
///   robot_state.joint_state.name/position  optional: the robot's default joint values
///   world.collision_objects[]:
///     id                                   required, unique
///     header.frame_id                      optional, recorded (poses are taken in the world frame)
///     pose                                 optional (absent in older files): the object's pose
///     primitives[] + primitive_poses[]     type box [x, y, z] | sphere [r] | cylinder [height, r]
///     meshes[] + mesh_poses[]              vertices [{x, y, z}], triangles [{vertex_indices: [a, b, c]}]
/// Points and quaternions may be maps ({x, y, z}, MoveIt's own writer) or sequences ([x, y, z],
/// robowflex's writer, which MotionBenchMaker uses); a type may be a name or shape_msgs' number
/// (1 box, 2 sphere, 3 cylinder). Cones (type 4), planes, mesh `resource` files and octomaps are
/// refused with an error naming the line. Every error is one adsd::InputError
/// "FILE:LINE: field 'PATH': what is wrong".

#include <map>
#include <string>
#include <vector>

#include "adsd/mesh.h"

namespace adsd::planner {

/// \brief What a scene file says.
struct PlanningSceneYaml {
  std::string path;  ///< the file as given
  std::string name;  ///< `name`, or empty
  /// One mesh per collision object, named by its id, vertices in the WORLD frame (the planning
  /// frame): world_T_shape = object `pose` * the shape's primitive or mesh pose (MoveIt's
  /// composition). Boxes exact; spheres and cylinders as primitive_meshes.h's containing meshes.
  std::vector<Mesh> objects;
  /// Each primitive's own mesh (in `objects` too), world frame, named by its object's id: the
  /// solids of the arm scene (convex_solids.h), as MoveIt's primitives are.
  std::vector<Mesh> primitives;
  std::vector<std::string> frames;  ///< header.frame_id of each object ("" when absent)
  std::vector<int> lines;           ///< the line where each object starts
  /// `robot_state.joint_state`: joint name to position (radians or metres); empty when absent.
  std::map<std::string, double> defaultJointValues;
  /// What the file says that would change which states are free, and is not applied, one line
  /// each with the file and line: objects attached to the robot (`robot_state.
  /// attached_collision_objects`), `link_padding` and `link_scale` entries other than 0 and 1, and
  /// an `allowed_collision_matrix` with entries (an SRDF's <disable_collisions> is what is read).
  std::vector<std::string> warnings;
};

/// \brief Reads a scene file; throws adsd::InputError for a missing or unreadable file, broken
/// YAML, a missing required field, a value of the wrong type, a non-finite number, a coordinate
/// beyond 1e6, a non-positive dimension, a zero or non-unit quaternion (norm off 1 by more than
/// 1e-3), a triangle index out of range, primitives and primitive_poses (or meshes and
/// mesh_poses) of different lengths, an unknown or unsupported primitive type, an object without
/// shapes, a repeated id, or joint_state name and position lists of different lengths.
PlanningSceneYaml readPlanningSceneYaml(const std::string& path);

/// \brief The same from text; \p sourceName names it in messages.
PlanningSceneYaml parsePlanningSceneYaml(const std::string& text, const std::string& sourceName);

}  // namespace adsd::planner
