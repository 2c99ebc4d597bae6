#pragma once
/// \file
/// \brief Our short `.cfg` naming a MotionBenchMaker-format arm problem: the robot (URDF, SRDF),
/// the scene and request YAMLs, and where `package://` URIs are found (docs/problem-files.md).
///
///     # comments as in OMPL.app's files
///     [problem]
///     name = kr5_table_pick                                 # optional; default the file's stem
///     robot = ${ADSD_ROBOTS}/KR5/KR5 sixx R650.urdf
///     srdf = kr5.srdf                                       # optional
///     scene = scene.yaml
///     request = request.yaml
///     package_path = ${ADSD_ROBOTS}:more/packages           # optional, ':'-separated
///
/// Paths are relative to the `.cfg`'s directory. `${NAME}` is replaced by the environment
/// variable NAME; `${ADSD_ROBOTS}` defaults to `$HOME/.cache/adsd/robots` (where
/// problems/data/fetch_robots.sh puts the robots) when unset. Files are not opened here. Every
/// error is one adsd::InputError "FILE:LINE: key 'problem.KEY': what is wrong".

#include <optional>
#include <string>
#include <vector>

#include "adsd/planner/problem_file.h"

namespace adsd::planner {

/// \brief Everything an arm problem `.cfg` says, paths resolved.
struct MotionBenchMakerProblem {
  std::string path;       ///< the cfg as given
  std::string directory;  ///< where relative paths start
  std::string name;       ///< `name`, or the file's stem
  std::string robotPath;  ///< the URDF
  std::optional<std::string> srdfPath;
  std::string scenePath;    ///< the PlanningScene YAML
  std::string requestPath;  ///< the MotionPlanRequest YAML
  std::vector<std::string> packagePath;  ///< directories holding the packages of `package://` URIs
  SourceLocation robotLocation, srdfLocation, sceneLocation, requestLocation;
  /// One line each: unknown keys and sections ("FILE:LINE: ...").
  std::vector<std::string> warnings;
};

/// \brief Reads the cfg; throws adsd::InputError for a missing or unreadable file, a NUL byte or
/// control character, a line that is neither `key = value`, a section header nor a comment, a key
/// outside `[problem]`, a missing, empty or repeated key, an undefined `${NAME}` (other than
/// ADSD_ROBOTS) or an unterminated `${`.
MotionBenchMakerProblem readMotionBenchMakerProblem(const std::string& path);

/// \brief The same from text; \p sourceName names it in messages and \p directory resolves
/// relative paths.
MotionBenchMakerProblem parseMotionBenchMakerProblem(const std::string& text, const std::string& sourceName,
                                                     const std::string& directory);

/// \brief \p value with every `${NAME}` replaced (see the file comment); \p where names the line
/// in errors.
std::string expandPathVariables(const std::string& value, const SourceLocation& where);

/// \brief Where `${ADSD_ROBOTS}` points: the environment variable, or `$HOME/.cache/adsd/robots`.
std::string defaultRobotsDirectory();

}  // namespace adsd::planner
