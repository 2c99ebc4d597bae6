#pragma once
/// \file
/// \brief OMPL.app problem files (`.cfg`, shared/OMPLAPP-CFG.md): read into plain data.
///
/// Reading only parses and checks the text; meshes are loaded later (planning_problem.h). Every
/// error is an adsd::InputError with one line "FILE:LINE: key 'section.key': what is wrong".

#include <istream>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "adsd/mesh.h"
#include "adsd/planner/rigid_body_scene.h"

namespace adsd::planner {

/// \brief The longest time limit accepted (seconds): a problem file's [benchmark] time_limit, an
/// arm request's allowed_planning_time, `adsd plan` and `adsd benchmark --time`. OMPL adds it to
/// the system clock's now() in 64-bit nanoseconds, which overflow 2^63 ns (292 years) after 1970;
/// 1e8 s (3.2 years) stays far inside.
inline constexpr double kMaxTimeLimitSeconds = 1e8;

/// \brief Where a value came from, for messages.
struct SourceLocation {
  std::string file;
  int line = 0;  ///< 1-based; 0 when the value did not come from the file
  std::string key;  ///< full key, "section.key"

  /// \brief "FILE:LINE: key 'KEY'" (the prefix of every message about this value).
  std::string describe() const;
};

/// \brief Start or goal as written: position, yaw/angle theta, and (SE(3)) the rotation axis.
struct ProblemPose {
  Vec3 position = Vec3::Zero();  ///< z is 0 for SE(2)
  double theta = 0.0;            ///< radians: yaw for SE(2), rotation angle about axis for SE(3)
  Vec3 axis = Vec3::UnitZ();     ///< SE(3) only; need not be normalized
  SourceLocation location;       ///< the `start.x` / `goal.x` line
  /// The `.x`, `.y` and `.z` lines (z: SE(3) only), for a message about one coordinate.
  std::array<SourceLocation, 3> positionLocations;

  /// \brief The pose this describes: translation then rotation (axis-angle about the normalized
  /// axis; about z for SE(2)).
  Pose toPose() const;
};

/// \brief The optimization objective.
enum class ObjectiveKind {
  length,           ///< path length
  maxMinClearance,  ///< maximize the minimum clearance along the path
};

/// \brief `[problem] objective` value to kind: the value may be a prefix of a known name (as in
/// OMPL.app); throws InputError at \p where for an unknown or ambiguous value.
ObjectiveKind parseObjective(const std::string& value, const SourceLocation& where);

/// \brief A `key = value` line kept for later (space-information or planner parameters).
struct Setting {
  std::string key;  ///< without the section prefix
  std::string value;
  SourceLocation location;
};

/// \brief One `[planner]` entry: `NAME=` and the `NAME.param=value` lines that follow it.
struct PlannerEntry {
  std::string name;   ///< lower-case OMPL.app planner name (rrtconnect, prm, ...)
  std::string label;  ///< `NAME.name=Label`, or the name
  std::vector<Setting> parameters;
  SourceLocation location;
};

/// \brief The `[benchmark]` section (parsed for the benchmark command; absent keys stay empty).
struct BenchmarkSection {
  std::optional<double> timeLimit;  ///< seconds per run
  std::optional<double> memoryLimit;  ///< MB per run
  std::optional<int> runCount;
  std::optional<std::string> output;  ///< resolved against the cfg's directory
  SourceLocation outputLocation;      ///< the `output` line, when given
  std::optional<bool> simplify;
  std::optional<std::string> savePaths;  ///< "all" or "shortest"
  SourceLocation savePathsLocation;      ///< the `save_paths` line, when given
};

/// \brief Everything a `.cfg` says.
struct ProblemFile {
  std::string path;       ///< the cfg as given
  std::string directory;  ///< where relative mesh paths start
  std::string name;       ///< `[problem] name`, or the file's stem
  RigidBodySpace space = RigidBodySpace::se3;
  std::string robotPath;  ///< resolved against `directory`
  std::string worldPath;
  SourceLocation robotLocation;
  SourceLocation worldLocation;
  ProblemPose start;
  ProblemPose goal;
  /// `volume.min/max`: position bounds (z ignored for SE(2)); empty when the file has none.
  std::optional<Eigen::AlignedBox3d> volume;
  ObjectiveKind objective = ObjectiveKind::length;
  std::optional<double> objectiveThreshold;
  double goalThreshold = 1e-6;  ///< OMPL.app's default goal tolerance
  /// Other `[problem]` keys (sampler, longest_valid_segment_fraction, ...), for
  /// si->params().setParam.
  std::vector<Setting> spaceParameters;
  BenchmarkSection benchmark;
  std::vector<PlannerEntry> planners;
  /// One line each: unknown keys and sections, unknown planners ("FILE:LINE: ...").
  std::vector<std::string> warnings;
};

/// \brief Reads and checks a problem file. Throws adsd::InputError for a missing or unreadable
/// file, a syntax error, a control character in a line (CR LF line ends are accepted), a missing
/// or repeated key, a value of the wrong type or not finite, a coordinate beyond 1e75 in
/// magnitude, an inconsistent SE(2)/SE(3) key set, an inverted volume, a time limit beyond 1e8 s,
/// a `control` key (kinodynamic problems are out of scope), or a repeated [problem] or [benchmark]
/// section. Every value handed to OMPL as text (the space information's
/// `longest_valid_segment_fraction` and `valid_segment_count_factor`, and each parameter the
/// registry's planners declare) is checked against what OMPL converts and accepts, so that OMPL
/// neither throws on it nor misreads it (OMPL reads "1e3" as the count 1, "-1" as 2^32 - 1 and
/// "no" as true). Mesh files are not opened.
ProblemFile readProblemFile(const std::string& path);

/// \brief Whether planner parameter \p name is a switch (0, 1, true or false) of an OMPL planner.
bool isPlannerSwitch(const std::string& name);

/// \brief The same from text; \p sourceName names it in messages and \p directory resolves
/// relative mesh paths.
ProblemFile parseProblemFile(std::istream& in, const std::string& sourceName, const std::string& directory);

}  // namespace adsd::planner
