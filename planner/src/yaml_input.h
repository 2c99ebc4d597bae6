#pragma once
/// \file
/// \brief Internal: reading a YAML file with yaml-cpp so that every failure is one adsd::InputError
/// "FILE:LINE: field 'PATH': what is wrong", and numbers are read as the C locale writes them.
///
/// Shared by the PlanningScene and MotionPlanRequest readers (planning_scene_yaml.cpp,
/// motion_plan_request_yaml.cpp). Not installed.

#include <cstdint>
#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <yaml-cpp/yaml.h>

#include "adsd/mesh.h"

namespace adsd::planner::yaml {

/// \brief One field of the document: its node and its path from the root ("world.collision_objects[2].id").
struct Field {
  YAML::Node node;  ///< undefined when the field is absent
  std::string path;
  int line = 0;  ///< 1-based line of the node, or of the nearest present ancestor when absent
};

/// \brief The document being read: its name for messages and a budget of scalars.
///
/// The budget: in a YAML text each scalar the readers take costs two units (its element and its
/// text) and takes at least two bytes (itself and a separator), and each collection element costs
/// one and takes at least three, so a file of n bytes costs at most about n units. Aliases
/// (`*name`) may repeat a node any number of times without growing the text, so that a few
/// kilobytes could ask for 10^9 vertices; more than 4 n + 1024 units is refused before the work
/// grows (no file without aliases comes near it).
class Document {
 public:
  /// \brief Parses \p text; a YAML syntax error is an InputError naming \p source and its line.
  Document(const std::string& text, std::string source);

  Field root() const;
  const std::string& source() const { return source_; }

  /// \brief "SOURCE:LINE: field 'PATH': " + \p what, as an InputError.
  [[noreturn]] void fail(const Field& f, const std::string& what) const;

  /// \brief The child \p key of a map field; absent children are returned undefined (check
  /// present()). A field that is not a map is an error.
  Field child(const Field& map, const std::string& key) const;
  /// \brief The child \p key, which must be present.
  Field required(const Field& map, const std::string& key) const;
  /// \brief Element \p i of a sequence field.
  Field element(const Field& sequence, std::size_t i) const;

  /// \brief Checks the field is a sequence (an absent field is an error) and returns its length.
  std::size_t sequenceLength(const Field& f) const;
  /// \brief Checks the field is a map.
  void requireMap(const Field& f) const;
  /// \brief The keys of map \p map that are not among \p known, each as the child field it
  /// names (its path and line), in the file's order; a key that is not a scalar is an error.
  std::vector<Field> keysOutside(const Field& map, std::initializer_list<const char*> known) const;

  /// \brief A scalar as text (counted against the budget).
  std::string text(const Field& f) const;
  /// \brief A finite decimal number, read in the C locale; YAML's .inf and .nan are refused.
  double number(const Field& f) const;
  /// \brief A whole number from 0 to \p most.
  std::uint64_t whole(const Field& f, std::uint64_t most) const;

  /// \brief A geometry_msgs/Point: a map {x, y, z} (as MoveIt's own YAML writes it) or a sequence
  /// [x, y, z] (as robowflex, which MotionBenchMaker uses, writes it); each coordinate finite and
  /// within kMaxSceneCoordinate. Absent: zero.
  Vec3 point(const Field& f) const;
  /// \brief A geometry_msgs/Quaternion {x, y, z, w} or [x, y, z, w], normalized; one whose norm is
  /// farther than kQuaternionNormTolerance from 1 is an error. Absent: the identity.
  Eigen::Quaterniond quaternion(const Field& f) const;
  /// \brief A geometry_msgs/Pose {position, orientation}. Absent: the identity.
  Pose pose(const Field& f) const;

 private:
  void spend(const Field& f) const;

  std::string source_;
  YAML::Node root_;
  std::size_t budget_;
  mutable std::size_t spent_ = 0;
};

/// \brief \p text in single quotes for a message: shortened to 60 characters, control characters
/// shown as '?', so that a message stays one line whatever the file holds.
std::string quoted(const std::string& text);

/// \brief A sensor_msgs/JointState's `name` and `position` lists as a map, with the line of each
/// position; lists of different lengths, a repeated name or an empty name are errors.
struct JointValues {
  std::map<std::string, double> values;
  std::map<std::string, int> lines;
};
JointValues jointState(const Document& doc, const Field& jointState);

/// Largest |coordinate| or length accepted in a scene (metres): 1e6 m is far beyond any robot's
/// workspace, and keeps every transformed vertex far inside adsd::Mesh's limit (1e75), so that a
/// bad number is reported here with its line rather than by the mesh without one.
constexpr double kMaxSceneCoordinate = 1e6;

/// How far from 1 a quaternion's norm may be (dimensionless). Scene files print quaternions with
/// 6 to 17 digits; a norm off by 1e-3 is a rounding of a unit quaternion, and it is normalized.
/// Farther (a zero quaternion, MoveIt's default when the orientation is left out of a message
/// built by hand, or a typo) is refused rather than guessed.
constexpr double kQuaternionNormTolerance = 1e-3;

}  // namespace adsd::planner::yaml
