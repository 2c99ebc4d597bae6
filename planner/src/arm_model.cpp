#include "adsd/planner/arm_model.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>

#include <console_bridge/console.h>

#include <tinyxml.h>
#include <urdf_parser/urdf_parser.h>

#include "adsd/error.h"
#include "adsd/io/load_mesh.h"
#include "adsd/tolerances.h"
#include "adsd/planner/primitive_meshes.h"
#include "input_file.h"
#include "xml_input.h"

namespace adsd::planner {

namespace fs = std::filesystem;

std::size_t ArmModel::jointIndex(const std::string& jointName) const {
  for (std::size_t i = 0; i < activeJoints.size(); ++i) {
    if (joints[activeJoints[i]].name == jointName) return i;
  }
  throw InputError(sourceFile + ": no movable joint named '" + jointName + "'");
}

double defaultPosition(const ArmJoint& joint) {
  if (joint.type == ArmJointType::continuous || (joint.lower <= 0.0 && 0.0 <= joint.upper)) return 0.0;
  return 0.5 * (joint.lower + joint.upper);
}

std::pair<double, double> ArmModel::positionRange(const ArmJoint& joint) const {
  // A joint held outside the planning group (holdJointsOutside) stands within its limits.
  if (joint.locked) return {joint.lockedPosition, joint.lockedPosition};
  if (joint.mimicCoordinate < 0) return {joint.lower, joint.upper};
  const ArmJoint& leader = joints[activeJoints[static_cast<std::size_t>(joint.mimicCoordinate)]];
  const double a = joint.mimicMultiplier * leader.lower + joint.mimicOffset;
  const double b = joint.mimicMultiplier * leader.upper + joint.mimicOffset;
  return {std::min(a, b), std::max(a, b)};
}

std::size_t ArmModel::linkIndex(const std::string& linkName) const {
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (links[i].name == linkName) return i;
  }
  throw InputError(sourceFile + ": no link named '" + linkName + "'");
}

void ArmModel::buildHierarchies() {
  for (ArmLink& link : links) {
    if (link.collision && !link.collision->hierarchy()) link.collision->buildHierarchy();
  }
}

namespace {

/// The most links a URDF may have. Robots have tens (the WAM 9, Atlas 35, DRC-Hubo 52); urdfdom's
/// parse recurses once per level of the tree and crashed (stack overflow) on a chain of 200 000
/// fixed links, and `adsd srdf` took 72 s and 2.7 GB on 100 000 (0.9 s on 10 000).
constexpr std::size_t kMaxUrdfLinks = 10000;

/// What urdfdom does not say clearly (it logs a line and returns null, or drops an element),
/// checked on the XML first so that the error names the joint or link: joint types, the tree's
/// shape; and what urdfdom loses: the file order of the joints (it keeps them in a map by name)
/// and the lines of the links and their <collision> elements.
struct UrdfOutline {
  std::map<std::string, int> rank;                         ///< joint name -> position in the file
  std::map<std::string, int> linkLine;                     ///< link name -> line of its <link>
  std::map<std::string, int> jointLine;                    ///< joint name -> line of its <joint>
  std::map<std::string, std::vector<int>> collisionLines;  ///< link name -> line of each <collision>
};

UrdfOutline checkTreeShape(const std::string& path, const std::string& text) {
  TiXmlDocument doc;
  xml::parseXml(path, text, doc);  // its nesting checked before any recursive parser, ours or urdfdom's
  const TiXmlElement* robot = doc.FirstChildElement("robot");
  if (!robot) throw InputError(path + ": no <robot> element: not a URDF file");
  UrdfOutline outline;
  std::set<std::string> linkNames;
  for (const TiXmlElement* l = robot->FirstChildElement("link"); l; l = l->NextSiblingElement("link")) {
    const char* name = l->Attribute("name");
    if (!name) throw InputError(path + ":" + std::to_string(l->Row()) + ": a <link> without a name");
    // Refused here, as urdfdom does, so that the lines below belong to one link each.
    if (!linkNames.insert(name).second) {
      throw InputError(path + ":" + std::to_string(l->Row()) + ": two links are named '" + name + "'");
    }
    outline.linkLine[name] = l->Row();
    std::vector<int>& lines = outline.collisionLines[name];
    for (const TiXmlElement* c = l->FirstChildElement("collision"); c; c = c->NextSiblingElement("collision")) {
      lines.push_back(c->Row());
      // urdfdom reads the first shape of a <geometry> and drops the others without a word (as
      // MoveIt then does): a box after a sphere went unchecked (an outside review).
      const TiXmlElement* geometry = c->FirstChildElement("geometry");
      const TiXmlElement* shape = geometry ? geometry->FirstChildElement() : nullptr;
      if (shape && shape->NextSiblingElement()) {
        throw InputError(path + ":" + std::to_string(shape->NextSiblingElement()->Row()) + ": link '" + name +
                         "': a second shape in one <geometry>, which urdfdom would drop; give each shape a " +
                         "<collision> element of its own");
      }
    }
  }
  if (linkNames.empty()) throw InputError(path + ": no <link> elements: a robot needs at least one link");
  if (linkNames.size() > kMaxUrdfLinks) {
    throw InputError(path + ": " + std::to_string(linkNames.size()) + " <link> elements, more than the " +
                     std::to_string(kMaxUrdfLinks) + " the reader takes (a robot has tens)");
  }
  std::map<std::string, std::string> parentJointOf;  // child link -> joint
  int rank = 0;
  for (const TiXmlElement* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
    const std::string where = path + ":" + std::to_string(j->Row());
    const char* name = j->Attribute("name");
    if (!name) throw InputError(where + ": a <joint> without a name");
    const char* type = j->Attribute("type");
    const std::string t = type ? type : "";
    if (t == "floating" || t == "planar") {
      throw InputError(where + ": joint '" + name + "' is " + t +
                       ": only revolute, continuous, prismatic and fixed joints are supported");
    }
    if (t != "revolute" && t != "continuous" && t != "prismatic" && t != "fixed") {
      throw InputError(where + ": joint '" + name + "' has unknown type '" + t +
                       "' (revolute, continuous, prismatic or fixed)");
    }
    const TiXmlElement* parent = j->FirstChildElement("parent");
    const TiXmlElement* child = j->FirstChildElement("child");
    const char* parentLink = parent ? parent->Attribute("link") : nullptr;
    const char* childLink = child ? child->Attribute("link") : nullptr;
    if (!parentLink || !childLink) throw InputError(where + ": joint '" + std::string(name) + "' needs <parent link=> and <child link=>");
    for (const char* l : {parentLink, childLink}) {
      if (!linkNames.count(l)) throw InputError(where + ": joint '" + std::string(name) + "' names link '" + l + "', which is not defined");
    }
    if (std::string(parentLink) == childLink) {
      throw InputError(where + ": joint '" + std::string(name) + "' joins link '" + parentLink + "' to itself: a joint cycle");
    }
    const auto [it, fresh] = parentJointOf.emplace(childLink, name);
    if (!fresh) {
      throw InputError(where + ": link '" + std::string(childLink) + "' is the child of joints '" + it->second +
                       "' and '" + name + "': a joint cycle (a URDF is a tree)");
    }
    if (!outline.rank.emplace(name, rank++).second) throw InputError(where + ": two joints are named '" + std::string(name) + "'");
    outline.jointLine[name] = j->Row();
  }
  std::vector<std::string> roots;
  for (const std::string& l : linkNames) {
    if (!parentJointOf.count(l)) roots.push_back(l);
  }
  if (roots.empty()) throw InputError(path + ": every link has a parent: a joint cycle, no root link");
  if (roots.size() > 1) {
    throw InputError(path + ": " + std::to_string(roots.size()) + " root links ('" + roots[0] + "', '" + roots[1] +
                     "'...): the links must form one tree");
  }
  // One root and one parent per link: the links reachable from the root are a tree; any link not
  // reachable sits on a cycle.
  std::map<std::string, std::vector<std::string>> children;
  for (const TiXmlElement* j = robot->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint")) {
    children[j->FirstChildElement("parent")->Attribute("link")].push_back(j->FirstChildElement("child")->Attribute("link"));
  }
  std::set<std::string> reached;
  std::vector<std::string> stack = {roots[0]};
  while (!stack.empty()) {
    const std::string l = stack.back();
    stack.pop_back();
    reached.insert(l);
    for (const std::string& c : children[l]) stack.push_back(c);
  }
  for (const std::string& l : linkNames) {
    if (!reached.count(l)) throw InputError(path + ": link '" + l + "' lies on a joint cycle (joint '" + parentJointOf[l] + "')");
  }
  return outline;
}

Pose toPose(const urdf::Pose& p) {
  Pose pose = Pose::Identity();
  pose.linear() = Eigen::Quaterniond(p.rotation.w, p.rotation.x, p.rotation.y, p.rotation.z).normalized().toRotationMatrix();
  pose.translation() = Vec3(p.position.x, p.position.y, p.position.z);
  return pose;
}

/// The smallest |factor| of a <mesh scale> (dimensionless). Real files scale by 1e-3 at the least
/// (millimetres to metres); 1e-6 leaves room, and below it a link shrinks under a micrometre, far
/// from any planning tolerance: a typo or a 0, as in scale="0 1 1".
constexpr double kMinMeshScale = 1e-6;

/// A vector as "(x, y, z)" for a message, 6 significant digits.
std::string describe(const Vec3& v) {
  std::ostringstream out;
  out << "(" << v.x() << ", " << v.y() << ", " << v.z() << ")";
  return out.str();
}

/// Resolves a mesh file name (see readUrdf()); throws naming the link when nothing is found.
std::string resolveMeshPath(const std::string& uri, const fs::path& urdfDir, const std::vector<std::string>& search,
                            const std::string& where) {
  const std::string package = "package://", file = "file://";
  if (uri.rfind(package, 0) == 0) {
    const std::string rest = uri.substr(package.size());
    const std::size_t slash = rest.find('/');
    const std::string name = rest.substr(0, slash);
    const std::string inside = slash == std::string::npos ? "" : rest.substr(slash + 1);
    for (const std::string& dir : search) {
      for (const fs::path& candidate : {fs::path(dir) / name / inside, fs::path(dir) / inside}) {
        std::error_code ec;
        if (fs::is_regular_file(candidate, ec)) return candidate.string();
      }
    }
    std::string tried;
    for (const std::string& dir : search) tried += (tried.empty() ? "" : ", ") + dir;
    throw InputError(where + ": mesh '" + uri + "' not found in the package search path (" +
                     (tried.empty() ? std::string("empty: give the directories that hold package '") + name + "'" : tried) + ")");
  }
  fs::path p = uri.rfind(file, 0) == 0 ? fs::path(uri.substr(file.size())) : fs::path(uri);
  if (p.is_relative()) p = urdfDir / p;
  std::error_code ec;
  if (fs::is_directory(p, ec)) throw InputError(where + ": mesh '" + uri + "' is a directory (" + p.string() + ")");
  if (fs::exists(p, ec) && !fs::is_regular_file(p, ec)) {
    throw InputError(where + ": mesh '" + uri + "' is a device, a pipe or a socket, not a file (" + p.string() + ")");
  }
  if (!fs::is_regular_file(p, ec)) throw InputError(where + ": mesh '" + uri + "' not found (" + p.string() + ")");
  return p.string();
}

/// One <collision> element's geometry as a mesh in its own frame.
Mesh geometryMesh(const urdf::Geometry& g, const fs::path& urdfDir, const std::vector<std::string>& search,
                  const std::string& where) {
  switch (g.type) {
    case urdf::Geometry::BOX: {
      const auto& b = static_cast<const urdf::Box&>(g);
      return boxMesh(Vec3(b.dim.x, b.dim.y, b.dim.z), where + " box");
    }
    case urdf::Geometry::CYLINDER: {
      const auto& c = static_cast<const urdf::Cylinder&>(g);
      return cylinderMesh(c.radius, c.length, where + " cylinder");
    }
    case urdf::Geometry::SPHERE:
      return sphereMesh(static_cast<const urdf::Sphere&>(g).radius, where + " sphere");
    case urdf::Geometry::MESH: {
      const auto& m = static_cast<const urdf::Mesh&>(g);
      const std::string path = resolveMeshPath(m.filename, urdfDir, search, where);
      Mesh loaded = [&] {
        try {
          // As the ROS tools read a URDF's meshes: a COLLADA file's coordinates in the link frame,
          // not turned by its <up_axis> (an outside review: a Z_UP bar came out lying along y).
          return io::loadMesh(path, {}, io::ColladaUpAxis::asWritten);
        } catch (const InputError& e) {
          throw InputError(where + ": mesh '" + m.filename + "': " + e.what());
        }
      }();
      const Vec3 scale(m.scale.x, m.scale.y, m.scale.z);
      if (scale == Vec3::Ones()) return loaded;
      // A negative factor mirrors the mesh (left and right arms share one); a zero one flattens the
      // link, which would then be checked as a sheet or a point.
      if (!scale.allFinite() || scale.cwiseAbs().minCoeff() < kMinMeshScale) {
        throw InputError(where + ": mesh '" + m.filename + "' <mesh scale> must be finite with each factor at least " +
                         "1e-6 in magnitude, got " + describe(scale));
      }
      std::vector<Vec3> v = loaded.vertices();
      for (Vec3& p : v) {
        p = p.cwiseProduct(scale);
        if (p.cwiseAbs().maxCoeff() > tolerance::kMaxCoordinate) {
          throw InputError(where + ": mesh '" + m.filename + "' <mesh scale> " + describe(scale) +
                           " takes a vertex beyond 1e75, to " + describe(p));
        }
      }
      return Mesh(std::move(v), loaded.triangles(), loaded.name());
    }
  }
  throw InputError(where + ": collision geometry of unknown type");
}

/// Every <collision> element of a link, placed by its origin, in one mesh (link frame); its
/// primitive elements also as solids into \p solids (ArmLink::solids).
///
/// urdfdom drops a <collision> element it cannot read (a "nan", a scale of two numbers, an empty
/// <geometry>) after logging a line, and reads the rest: the link would silently go unchecked
/// for collisions. So every element of the XML must have come through.
std::optional<Mesh> linkCollisionMesh(const urdf::Link& link, const fs::path& urdfDir,
                                      const std::vector<std::string>& search, const std::string& path,
                                      const UrdfOutline& outline, const std::string& urdfdomSaid,
                                      std::vector<ConvexSolid>& solids) {
  std::vector<urdf::CollisionSharedPtr> elements = link.collision_array;
  if (elements.empty() && link.collision) elements.push_back(link.collision);
  const std::vector<int>& lines = outline.collisionLines.at(link.name);
  const std::string linkWhere = path + ":" + std::to_string(outline.linkLine.at(link.name)) + ": link '" + link.name + "'";
  if (elements.size() != lines.size()) {
    throw InputError(linkWhere + ": urdfdom read " + std::to_string(elements.size()) + " of its " +
                     std::to_string(lines.size()) + " <collision> elements (urdfdom: " +
                     (urdfdomSaid.empty() ? std::string("no reason given") : urdfdomSaid) +
                     "); refused rather than leave the link unchecked");
  }
  std::vector<Vec3> vertices;
  std::vector<TriangleIndices> triangles;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const urdf::CollisionSharedPtr& c = elements[k];
    const std::string where = path + ":" + std::to_string(lines[k]) + ": link '" + link.name + "'";
    if (!c || !c->geometry) throw InputError(where + ": a <collision> element without geometry");
    const Vec3 offset(c->origin.position.x, c->origin.position.y, c->origin.position.z);
    if (!offset.allFinite() || offset.cwiseAbs().maxCoeff() > tolerance::kMaxCoordinate) {
      throw InputError(where + ": <collision> <origin xyz> must be finite and within 1e75, got " + describe(offset));
    }
    const Mesh part = geometryMesh(*c->geometry, urdfDir, search, where);
    const Pose origin = toPose(c->origin);
    const auto first = static_cast<std::uint32_t>(vertices.size());
    const bool primitive = c->geometry->type != urdf::Geometry::MESH;
    for (const Vec3& p : part.vertices()) {
      const Vec3 placed = origin * p;
      // Each summand is within 1e75, but their sum may not be; Mesh would then name only the link.
      if (placed.cwiseAbs().maxCoeff() > tolerance::kMaxCoordinate) {
        throw InputError(where + ": placed by its <origin>, the collision geometry reaches " + describe(placed) +
                         ", beyond 1e75");
      }
      vertices.push_back(placed);
    }
    if (primitive) {
      Mesh placed(std::vector<Vec3>(vertices.begin() + first, vertices.end()), part.triangles(), link.name);
      if (std::optional<ConvexSolid> solid = convexSolidOf(placed)) solids.push_back(std::move(*solid));
    }
    for (const TriangleIndices& t : part.triangles()) triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
  }
  if (triangles.empty()) return std::nullopt;
  try {
    return Mesh(std::move(vertices), std::move(triangles), link.name);
  } catch (const InputError& e) {
    throw InputError(linkWhere + ": its collision geometry: " + e.what());
  }
}

ArmJoint convertJoint(const urdf::Joint& uj, std::size_t parentLink, std::size_t childLink, const std::string& urdfPath,
                      const UrdfOutline& outline) {
  ArmJoint j;
  j.name = uj.name;
  j.parentLink = parentLink;
  j.childLink = childLink;
  const std::string where = urdfPath + ":" + std::to_string(outline.jointLine.at(j.name)) + ": joint '" + j.name + "'";
  const urdf::Vector3& at = uj.parent_to_joint_origin_transform.position;
  const Vec3 offset(at.x, at.y, at.z);
  // Beyond 1e75 the child link's vertices would be beyond what the distance computation accepts.
  if (!offset.allFinite() || offset.cwiseAbs().maxCoeff() > tolerance::kMaxCoordinate) {
    throw InputError(where + ": <origin xyz> must be finite and within 1e75, got " + describe(offset));
  }
  j.origin = toPose(uj.parent_to_joint_origin_transform);
  switch (uj.type) {
    case urdf::Joint::REVOLUTE: j.type = ArmJointType::revolute; break;
    case urdf::Joint::CONTINUOUS: j.type = ArmJointType::continuous; break;
    case urdf::Joint::PRISMATIC: j.type = ArmJointType::prismatic; break;
    case urdf::Joint::FIXED: j.type = ArmJointType::fixed; break;
    default: throw InputError(where + ": unsupported joint type");  // refused by checkTreeShape already
  }
  if (j.type != ArmJointType::fixed) {
    const Vec3 axis(uj.axis.x, uj.axis.y, uj.axis.z);
    if (!axis.allFinite()) throw InputError(where + ": <axis xyz> must be finite, got " + describe(axis));
    // Scaled by its largest component first: the norm of (0, 0, 1e300) overflowed to inf and that
    // of (0, 0, 1e-170) underflowed to 0, either way no direction, though both name the z axis.
    const double largest = axis.cwiseAbs().maxCoeff();
    if (!(largest > 0.0)) throw InputError(where + ": the axis must be a non-zero vector");
    j.axis = (axis / largest).normalized();
  }
  if (j.type == ArmJointType::continuous) {
    j.lower = -std::acos(-1.0);
    j.upper = std::acos(-1.0);
  } else if (j.type != ArmJointType::fixed) {
    if (!uj.limits) throw InputError(where + ": a revolute or prismatic joint needs <limit lower= upper=>");
    j.lower = uj.limits->lower;
    j.upper = uj.limits->upper;
    // Within 1e75, so that the range upper - lower is finite too: [-1e308, 1e308] overflowed it,
    // and every sampled state came out invalid.
    const auto inRange = [](double x) { return std::isfinite(x) && std::fabs(x) <= tolerance::kMaxCoordinate; };
    if (!inRange(j.lower) || !inRange(j.upper) || j.lower > j.upper) {
      std::ostringstream got;
      got << "[" << j.lower << ", " << j.upper << "]";
      throw InputError(where + ": <limit lower= upper=> must be finite, within 1e75, with lower <= upper, got " +
                       got.str());
    }
    // MoveIt plans within a joint's <safety_controller> soft limits where it has one, cut to its
    // <limit> (its RobotModel's bounds from the URDF): a path between the two is one the robot's
    // controller would stop. urdfdom reads an absent soft limit as 0, and MoveIt takes that too.
    if (uj.safety) {
      const double softLower = uj.safety->soft_lower_limit, softUpper = uj.safety->soft_upper_limit;
      const double lower = std::max(j.lower, softLower), upper = std::min(j.upper, softUpper);
      if (!std::isfinite(softLower) || !std::isfinite(softUpper) || !(lower <= upper)) {
        std::ostringstream got;
        got << "[" << softLower << ", " << softUpper << "] and [" << j.lower << ", " << j.upper << "]";
        throw InputError(where + ": its <safety_controller soft_lower_limit= soft_upper_limit=> and <limit> must " +
                         "share a range (MoveIt plans within both), got " + got.str());
      }
      j.lower = lower;
      j.upper = upper;
    }
  }
  return j;
}

/// Points every mimic joint of \p model (not in the joint vector: readUrdf left it inactive) at the
/// coordinate it follows, through any chain of mimic joints, with the multipliers and offsets
/// composed: following g by (m1, o1) where g follows h by (m2, o2) is following h by
/// (m1 m2, m1 o2 + o1).
void resolveMimicJoints(const urdf::ModelInterface& urdf, const std::string& urdfPath, const UrdfOutline& outline,
                        ArmModel& model) {
  std::map<std::string, std::size_t> byName;
  for (std::size_t k = 0; k < model.joints.size(); ++k) byName[model.joints[k].name] = k;
  const auto inRange = [](double x) { return std::isfinite(x) && std::fabs(x) <= tolerance::kMaxCoordinate; };
  // Each joint's chain, once composed, is kept: a joint whose chain reaches a composed one stops
  // there. Walking every chain to its end was quadratic in a chain's length: 10 000 joints each
  // following the next took adsd srdf 37 s (an adversarial sweep).
  struct Composed {
    double multiplier = 1.0, offset = 0.0;
    std::size_t leader = 0;
  };
  std::vector<std::optional<Composed>> composed(model.joints.size());
  struct Step {
    std::size_t joint;
    double multiplier, offset;  // of the joint it follows
  };
  std::vector<Step> walk;  // the joints on the way to a composed chain or a leader
  for (std::size_t index = 0; index < model.joints.size(); ++index) {
    ArmJoint& joint = model.joints[index];
    const urdf::JointConstSharedPtr uj = urdf.getJoint(joint.name);
    if (!uj || !uj->mimic || joint.type == ArmJointType::fixed) continue;  // a fixed joint never moves
    const std::string where =
        urdfPath + ":" + std::to_string(outline.jointLine.at(joint.name)) + ": joint '" + joint.name + "'";
    joint.mimics = uj->mimic->joint_name;
    // Walk to the first joint that follows none or whose chain is composed; a link of the chain
    // is checked the first time a walk crosses it, so an error names the first joint (in the
    // URDF's order) whose chain holds the bad link.
    walk.clear();
    Composed end{1.0, 0.0, index};
    for (std::size_t at = index;;) {
      if (composed[at]) {
        end = *composed[at];
        break;
      }
      const urdf::JointConstSharedPtr follower = urdf.getJoint(model.joints[at].name);
      if (!follower->mimic) {
        end.leader = at;
        break;
      }
      if (walk.size() == model.joints.size()) throw InputError(where + ": its <mimic> chain comes back to itself");
      const double m = follower->mimic->multiplier, o = follower->mimic->offset;
      if (!inRange(m) || !inRange(o)) {
        std::ostringstream got;
        got << m << ", " << o;
        throw InputError(where + ": <mimic> of joint '" + follower->name +
                         "': multiplier and offset must be finite and within 1e75, got " + got.str());
      }
      const auto next = byName.find(follower->mimic->joint_name);
      if (next == byName.end() || model.joints[next->second].type == ArmJointType::fixed) {
        throw InputError(where + ": <mimic joint='" + follower->mimic->joint_name + "'> of joint '" + follower->name +
                         "' names no movable joint of the robot");
      }
      walk.push_back({at, m, o});
      at = next->second;
    }
    for (auto step = walk.rbegin(); step != walk.rend(); ++step) {  // compose from the leader's end back
      end = {step->multiplier * end.multiplier, step->multiplier * end.offset + step->offset, end.leader};
      composed[step->joint] = end;
    }
    const double multiplier = end.multiplier, offset = end.offset;
    const ArmJoint& lead = model.joints[end.leader];
    // Each link's numbers are within 1e75, but a chain multiplies them: six joints each following
    // the last by 1e75 overflowed to a pose with no finite entry, refused by the distance query
    // with no word of the file or the joint (an outside review).
    const double leaderReach = lead.locked ? std::fabs(lead.lockedPosition)
                                           : std::max(std::fabs(lead.lower), std::fabs(lead.upper));
    if (!inRange(multiplier) || !inRange(offset) || !inRange(std::fabs(multiplier) * leaderReach + std::fabs(offset))) {
      std::ostringstream got;
      got << multiplier << " and offset " << offset;
      throw InputError(where + ": its <mimic> chain to joint '" + lead.name + "' composes to multiplier " + got.str() +
                       ", which move it beyond 1e75");
    }
    // A continuous leader's angle wraps from pi to -pi: a follower at a multiple of it would jump
    // there, unless it turns and the multiple is whole (a whole number of turns is no turn).
    const bool wholeTurns = joint.type != ArmJointType::prismatic && multiplier == std::round(multiplier);
    if (lead.type == ArmJointType::continuous && !wholeTurns) {
      std::ostringstream why;
      why << where << ": follows continuous joint '" << lead.name << "' with multiplier " << multiplier
          << ", so it would jump where that joint's angle wraps at +-pi (only a turning joint at a whole multiple "
             "can follow a continuous one)";
      throw InputError(why.str());
    }
    if (lead.locked) {  // a locked leader locks its followers
      joint.locked = true;
      joint.lockedPosition = multiplier * lead.lockedPosition + offset;
      continue;
    }
    joint.mimicCoordinate = lead.active;
    joint.mimicMultiplier = multiplier;
    joint.mimicOffset = offset;
  }
}

/// What urdfdom reports through console_bridge while it parses one file. Its errors were printed
/// above our one-line error, several lines each with urdfdom's own source lines ("at line 440 in
/// ./urdf_parser/src/joint.cpp", easily taken for a line of the URDF); they join our message
/// instead. Warnings are still printed, on one line naming the file.
class UrdfdomMessages : public console_bridge::OutputHandler {
 public:
  explicit UrdfdomMessages(const std::string& urdfPath) : urdfPath_(urdfPath) {}
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    std::string line = text;
    std::replace(line.begin(), line.end(), '\n', ' ');
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) {
      errors_ += (errors_.empty() ? "" : "; ") + line;
    } else if (level == console_bridge::CONSOLE_BRIDGE_LOG_WARN) {
      std::cerr << urdfPath_ << ": urdfdom: " << line << '\n';
    }
  }
  /// The errors reported, in order, separated by "; ".
  const std::string& errors() const { return errors_; }

 private:
  const std::string& urdfPath_;
  std::string errors_;
};

/// urdfdom's parse, its errors collected into \p said (those of a model it reads after all are
/// about <collision> elements it dropped: linkCollisionMesh). console_bridge's handler is one for
/// the process, so that two threads reading URDF files take turns.
urdf::ModelInterfaceSharedPtr parseWithUrdfdom(const std::string& urdfPath, const std::string& text,
                                               std::string& said) {
  static std::mutex handlerInUse;
  const std::lock_guard<std::mutex> lock(handlerInUse);
  UrdfdomMessages messages(urdfPath);
  console_bridge::useOutputHandler(&messages);
  urdf::ModelInterfaceSharedPtr urdf;
  try {
    urdf = urdf::parseURDF(text);
  } catch (...) {
    console_bridge::restorePreviousOutputHandler();
    throw;
  }
  console_bridge::restorePreviousOutputHandler();
  said = messages.errors();
  if (!urdf || !urdf->getRoot()) {
    throw InputError(urdfPath + ": urdfdom cannot read this URDF" + (said.empty() ? std::string() : ": " + said));
  }
  return urdf;
}

/// How far a prismatic joint can move its child along its axis (0 for the other kinds).
double prismaticTravel(const ArmModel& model, const ArmJoint& joint) {
  if (joint.type != ArmJointType::prismatic) return 0.0;
  if (joint.locked) return std::fabs(joint.lockedPosition);
  if (joint.mimicCoordinate >= 0) {
    const ArmJoint& leader = model.joints[model.activeJoints[static_cast<std::size_t>(joint.mimicCoordinate)]];
    return std::fabs(joint.mimicMultiplier) * std::max(std::fabs(leader.lower), std::fabs(leader.upper)) +
           std::fabs(joint.mimicOffset);
  }
  return std::max(std::fabs(joint.lower), std::fabs(joint.upper));
}

/// Each joint's offset and travel is within 1e75 (convertJoint), but down a chain they add up,
/// and a link placed beyond 1e75 was refused only by the distance query, naming neither the file
/// nor the joint, after `adsd plan` had printed its summary. Bounds each link's distance from the
/// root by the sum of the offsets and travels above it.
void checkReach(const ArmModel& model, const std::string& urdfPath, const UrdfOutline& outline) {
  std::vector<double> reach(model.links.size(), 0.0);
  for (std::size_t i = 1; i < model.links.size(); ++i) {
    const ArmJoint& joint = model.joints[static_cast<std::size_t>(model.links[i].parentJoint)];
    reach[i] = reach[joint.parentLink] + joint.origin.translation().norm() + prismaticTravel(model, joint);
    if (reach[i] > tolerance::kMaxCoordinate) {
      std::ostringstream far;
      far << reach[i];
      throw InputError(urdfPath + ":" + std::to_string(outline.jointLine.at(joint.name)) + ": joint '" + joint.name +
                       "': its link '" + model.links[i].name +
                       "' may lie " + far.str() + " from the root link (the joints' offsets and prismatic travel " +
                       "down the chain added up), beyond 1e75");
    }
  }
}

}  // namespace

ArmModel readUrdf(const std::string& urdfPath, const std::vector<std::string>& packageSearchPath) {
  const std::string text = readInputFile(urdfPath, "URDF file");
  const UrdfOutline outline = checkTreeShape(urdfPath, text);
  std::string urdfdomSaid;
  const urdf::ModelInterfaceSharedPtr urdf = parseWithUrdfdom(urdfPath, text, urdfdomSaid);
  const fs::path urdfDir = fs::absolute(fs::path(urdfPath)).parent_path();

  ArmModel model;
  model.name = urdf->getName();
  model.sourceFile = urdfPath;
  // Depth first from the root, children in file order of their joints. A joint is numbered when
  // its child link is visited, so that joints[k] carries links[k + 1].
  struct Visit {
    urdf::LinkConstSharedPtr link;
    std::size_t parentLink;  // unused for the root
  };
  std::vector<Visit> stack = {{urdf->getRoot(), 0}};
  while (!stack.empty()) {
    const Visit visit = stack.back();
    stack.pop_back();
    const std::size_t linkIndex = model.links.size();
    ArmLink link;
    link.name = visit.link->name;
    if (linkIndex > 0) {
      model.joints.push_back(convertJoint(*visit.link->parent_joint, visit.parentLink, linkIndex, urdfPath, outline));
      link.parentJoint = static_cast<int>(model.joints.size() - 1);
      ArmJoint& joint = model.joints.back();
      joint.locked = joint.type != ArmJointType::fixed && joint.type != ArmJointType::continuous &&
                     joint.lower == joint.upper && !visit.link->parent_joint->mimic;
      if (joint.locked) joint.lockedPosition = joint.lower;
      if (joint.type != ArmJointType::fixed && !joint.locked && !visit.link->parent_joint->mimic) {
        model.activeJoints.push_back(model.joints.size() - 1);
        model.joints.back().active = static_cast<int>(model.activeJoints.size() - 1);
      }
    }
    link.collision =
        linkCollisionMesh(*visit.link, urdfDir, packageSearchPath, urdfPath, outline, urdfdomSaid, link.solids);
    model.links.push_back(std::move(link));

    std::vector<urdf::JointSharedPtr> childJoints = visit.link->child_joints;
    std::sort(childJoints.begin(), childJoints.end(), [&](const urdf::JointSharedPtr& a, const urdf::JointSharedPtr& b) {
      return outline.rank.at(a->name) < outline.rank.at(b->name);
    });
    // Pushed in reverse, so that the first child in the file is visited first.
    for (auto it = childJoints.rbegin(); it != childJoints.rend(); ++it) {
      stack.push_back({urdf->getLink((*it)->child_link_name), linkIndex});
    }
  }
  resolveMimicJoints(*urdf, urdfPath, outline, model);
  checkReach(model, urdfPath, outline);
  return model;
}

void holdJointsOutside(ArmModel& model, const std::vector<std::string>& planned, const std::vector<double>& q) {
  const auto isPlanned = [&](const std::string& name) {
    return std::find(planned.begin(), planned.end(), name) != planned.end();
  };
  std::vector<int> renumbered(model.activeJoints.size(), -1);
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < model.activeJoints.size(); ++i) {
    ArmJoint& j = model.joints[model.activeJoints[i]];
    if (isPlanned(j.name)) {
      renumbered[i] = static_cast<int>(kept.size());
      kept.push_back(model.activeJoints[i]);
    } else {
      j.locked = true;
      j.lockedPosition = q[i];
    }
  }
  for (ArmJoint& j : model.joints) {
    if (j.active >= 0) j.active = renumbered[static_cast<std::size_t>(j.active)];
    if (j.mimicCoordinate < 0) continue;
    const int leader = renumbered[static_cast<std::size_t>(j.mimicCoordinate)];
    if (leader >= 0) {
      j.mimicCoordinate = leader;
    } else {
      j.locked = true;
      j.lockedPosition = j.mimicMultiplier * q[static_cast<std::size_t>(j.mimicCoordinate)] + j.mimicOffset;
      j.mimicCoordinate = -1;
    }
  }
  model.activeJoints = std::move(kept);
}

}  // namespace adsd::planner
