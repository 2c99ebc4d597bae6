#include "adsd/planner/planning_scene_yaml.h"

#include <cmath>
#include <set>

#include "adsd/error.h"
#include "adsd/planner/primitive_meshes.h"
#include "input_file.h"
#include "yaml_input.h"

// The format, as relied on here (public sources read 2026-11-25):
// - moveit_msgs/CollisionObject: header, pose ("the object's pose relative to the header frame;
//   all shapes are relative to this pose", added in ROS Noetic / MoveIt 1.1; older messages have
//   no object pose and give the shapes' poses in the header frame), id, primitives[] with
//   primitive_poses[], meshes[] with mesh_poses[], planes[] with plane_poses[], operation.
// - shape_msgs/SolidPrimitive: type BOX=1, SPHERE=2, CYLINDER=3, CONE=4; dimensions BOX_X, BOX_Y,
//   BOX_Z (full side lengths); SPHERE_RADIUS; CYLINDER_HEIGHT, CYLINDER_RADIUS (height first),
//   centred on the pose, the cylinder's axis along z.
// - shape_msgs/Mesh: vertices[] (geometry_msgs/Point), triangles[] with vertex_indices[3].
// - robowflex's YAML conversion (robowflex_library yaml.cpp, which writes MotionBenchMaker's
//   scene files): a type as the lower-case name ("box", "sphere", "cylinder", "cone"), points as
//   flow sequences [x, y, z], quaternions as [x, y, z, w], the header's frame_id left out when it
//   is "world", mesh triangles as index triples.

namespace adsd::planner {

namespace {

using yaml::Document;
using yaml::Field;

enum class PrimitiveType { box, sphere, cylinder };

PrimitiveType primitiveType(const Document& doc, const Field& type) {
  std::string t = doc.text(type);
  for (char& c : t) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (t == "box" || t == "1") return PrimitiveType::box;
  if (t == "sphere" || t == "2") return PrimitiveType::sphere;
  if (t == "cylinder" || t == "3") return PrimitiveType::cylinder;
  if (t == "cone" || t == "4") {
    doc.fail(type, "cones are not supported (box, sphere and cylinder are; see docs/problem-files.md)");
  }
  doc.fail(type, "unknown primitive type " + yaml::quoted(doc.text(type)) +
                     " (expected box, sphere or cylinder, or 1, 2, 3)");
}

/// A dimension: finite, positive, within kMaxSceneCoordinate.
double dimension(const Document& doc, const Field& f) {
  const double x = doc.number(f);
  if (!(x > 0.0)) doc.fail(f, "a dimension must be > 0, got " + doc.text(f));
  if (x > yaml::kMaxSceneCoordinate) doc.fail(f, "a dimension beyond 1e6");
  return x;
}

/// A primitive as a mesh in its own frame.
Mesh primitiveMesh(const Document& doc, const Field& primitive, const std::string& id) {
  const PrimitiveType type = primitiveType(doc, doc.required(primitive, "type"));
  const Field dims = doc.required(primitive, "dimensions");
  const std::size_t n = doc.sequenceLength(dims);
  const std::size_t expected = type == PrimitiveType::box ? 3 : type == PrimitiveType::sphere ? 1 : 2;
  if (n != expected) {
    const char* form = type == PrimitiveType::box      ? "[x, y, z]"
                       : type == PrimitiveType::sphere ? "[radius]"
                                                       : "[height, radius]";
    doc.fail(dims, "expected " + std::to_string(expected) + " dimensions " + form + ", got " + std::to_string(n));
  }
  std::vector<double> d;
  for (std::size_t i = 0; i < n; ++i) d.push_back(dimension(doc, doc.element(dims, i)));
  switch (type) {
    case PrimitiveType::box: return boxMesh(Vec3(d[0], d[1], d[2]), id);
    case PrimitiveType::sphere: return sphereMesh(d[0], id);
    default: return cylinderMesh(d[1], d[0], id);  // MoveIt: [height, radius]
  }
}

/// A shape_msgs/Mesh in its own frame.
Mesh meshShape(const Document& doc, const Field& mesh, const std::string& id) {
  if (doc.child(mesh, "resource").node.IsDefined()) {
    doc.fail(doc.child(mesh, "resource"), "mesh files by resource are not supported; give vertices and triangles");
  }
  const Field vertices = doc.required(mesh, "vertices");
  const Field triangles = doc.required(mesh, "triangles");
  const std::size_t nv = doc.sequenceLength(vertices);
  const std::size_t nt = doc.sequenceLength(triangles);
  if (nv == 0) doc.fail(vertices, "no vertices");
  if (nt == 0) doc.fail(triangles, "no triangles");
  std::vector<Vec3> v;
  v.reserve(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    const Field p = doc.element(vertices, i);
    if (!p.node.IsDefined() || p.node.IsNull()) doc.fail(p, "expected a point");
    v.push_back(doc.point(p));
  }
  std::vector<TriangleIndices> t;
  t.reserve(nt);
  for (std::size_t i = 0; i < nt; ++i) {
    const Field triangle = doc.element(triangles, i);
    // {vertex_indices: [a, b, c]} (shape_msgs/MeshTriangle) or [a, b, c] (robowflex).
    const Field indices = triangle.node.IsDefined() && triangle.node.IsMap()
                              ? doc.required(triangle, "vertex_indices")
                              : triangle;
    if (doc.sequenceLength(indices) != 3) doc.fail(indices, "expected 3 vertex indices");
    TriangleIndices tri{};
    for (std::size_t k = 0; k < 3; ++k) {
      const Field index = doc.element(indices, k);
      tri[k] = static_cast<std::uint32_t>(doc.whole(index, nv - 1));
    }
    t.push_back(tri);
  }
  return Mesh(std::move(v), std::move(t), id);
}

/// Appends \p part placed by \p pose to the object's vertices and triangles.
void append(const Mesh& part, const Pose& pose, std::vector<Vec3>& vertices, std::vector<TriangleIndices>& triangles) {
  const auto offset = static_cast<std::uint32_t>(vertices.size());
  for (const Vec3& v : part.vertices()) vertices.push_back(pose * v);
  for (TriangleIndices t : part.triangles()) {
    for (auto& i : t) i += offset;
    triangles.push_back(t);
  }
}

/// Reads shapes[] with poses[] (primitives or meshes) of one object into its world-frame mesh;
/// with \p placed, each shape's world-frame mesh is added there too.
template <typename MakeShape>
void readShapes(const Document& doc, const Field& object, const char* shapesKey, const char* posesKey,
                const Pose& objectPose, MakeShape&& make, std::vector<Vec3>& vertices,
                std::vector<TriangleIndices>& triangles, std::vector<Mesh>* placed = nullptr) {
  const Field shapes = doc.child(object, shapesKey);
  if (!shapes.node.IsDefined()) return;
  const std::size_t n = doc.sequenceLength(shapes);
  const Field poses = doc.child(object, posesKey);
  const std::size_t m = poses.node.IsDefined() ? doc.sequenceLength(poses) : 0;
  if (n != m) {
    doc.fail(poses.node.IsDefined() ? poses : shapes,
             std::to_string(n) + " " + shapesKey + " but " + std::to_string(m) + " " + posesKey);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Field shape = doc.element(shapes, i);
    doc.requireMap(shape);
    const Mesh part = make(shape);
    const Field pose = doc.element(poses, i);
    doc.requireMap(pose);
    // MoveIt: world_T_shape = world_T_object * object_T_shape.
    const Pose shapePose = objectPose * doc.pose(pose);
    append(part, shapePose, vertices, triangles);
    if (placed != nullptr) {
      std::vector<Vec3> moved;
      for (const Vec3& v : part.vertices()) moved.push_back(shapePose * v);
      placed->emplace_back(std::move(moved), part.triangles(), part.name());
    }
  }
}

}  // namespace

PlanningSceneYaml parsePlanningSceneYaml(const std::string& text, const std::string& sourceName) {
  const Document doc(text, sourceName);
  const Field root = doc.root();
  doc.requireMap(root);
  PlanningSceneYaml scene;
  scene.path = sourceName;
  if (const Field name = doc.child(root, "name"); name.node.IsDefined() && !name.node.IsNull()) {
    scene.name = doc.text(name);
  }
  // Fields MoveIt applies and we do not, which change which states are free: said, not dropped
  // silently (an outside review: a 0.5 m box held in the hand overlapped an obstacle at the start,
  // and the plan was accepted without a word).
  auto ignored = [&](const Field& field, const std::string& what) {
    scene.warnings.push_back(sourceName + ":" + std::to_string(field.line) + ": " + what +
                             " not applied (not supported): the states checked are without it");
  };
  auto hasEntries = [](const Field& f) { return f.node.IsDefined() && !f.node.IsNull() && f.node.size() > 0; };
  // Keys a moveit_msgs/PlanningScene (and its World) does not have: a mistyped `wrld:` left the
  // scene without obstacles, and a file that is no scene at all was taken as an empty one, both
  // without a word.
  auto unknownKeys = [&](const Field& map, std::initializer_list<const char*> known, const char* message) {
    for (const Field& f : doc.keysOutside(map, known)) {
      scene.warnings.push_back(sourceName + ":" + std::to_string(f.line) + ": unknown key '" + f.path + "' ignored (" +
                               message + ")");
    }
  };
  unknownKeys(root,
              {"name", "robot_state", "robot_model_name", "fixed_frame_transforms", "allowed_collision_matrix",
               "link_padding", "link_scale", "object_colors", "world", "is_diff"},
              "not a field of a moveit_msgs/PlanningScene");
  if (const Field state = doc.child(root, "robot_state"); state.node.IsDefined() && !state.node.IsNull()) {
    const Field joints = doc.child(state, "joint_state");
    if (joints.node.IsDefined()) scene.defaultJointValues = yaml::jointState(doc, joints).values;
    if (const Field attached = doc.child(state, "attached_collision_objects"); hasEntries(attached)) {
      const std::size_t held = attached.node.size();
      ignored(attached, "robot_state.attached_collision_objects (" + std::to_string(held) +
                            (held == 1 ? " object" : " objects") + " held by the robot)");
    }
  }
  // link_padding and link_scale: MoveIt writes every link, at 0 and 1 when nothing is asked.
  auto anyEntryOtherThan = [&](const Field& list, const char* key, double neutral) {
    if (!list.node.IsDefined() || list.node.IsNull()) return false;
    if (!list.node.IsSequence()) return hasEntries(list);
    for (const YAML::Node& entry : list.node) {
      if (!entry.IsMap() || !entry[key].IsScalar()) return true;
      try {
        if (entry[key].as<double>() != neutral) return true;
      } catch (const YAML::Exception&) {
        return true;
      }
    }
    return false;
  };
  if (const Field padding = doc.child(root, "link_padding"); anyEntryOtherThan(padding, "padding", 0.0)) {
    ignored(padding, "link_padding other than 0");
  }
  if (const Field scale = doc.child(root, "link_scale"); anyEntryOtherThan(scale, "scale", 1.0)) {
    ignored(scale, "link_scale other than 1");
  }
  if (const Field matrix = doc.child(root, "allowed_collision_matrix"); hasEntries(matrix)) {
    ignored(matrix, "allowed_collision_matrix (give disabled pairs in an SRDF)");
  }

  const Field world = doc.child(root, "world");
  if (!world.node.IsDefined() || world.node.IsNull()) return scene;  // a scene without obstacles
  unknownKeys(world, {"collision_objects", "octomap"}, "not a field of a moveit_msgs/PlanningSceneWorld");
  if (const Field octomap = doc.child(world, "octomap"); octomap.node.IsDefined()) {
    doc.fail(octomap, "octomaps are not supported");
  }
  const Field objects = doc.child(world, "collision_objects");
  if (!objects.node.IsDefined() || objects.node.IsNull()) return scene;
  const std::size_t count = doc.sequenceLength(objects);
  std::map<std::string, int> idLines;
  for (std::size_t o = 0; o < count; ++o) {
    const Field object = doc.element(objects, o);
    doc.requireMap(object);
    // `pos:` for `pose:` left the object at the origin without a word (an outside review); refused
    // rather than warned of, as the start state's collision it caused was reported first.
    const std::vector<Field> other = doc.keysOutside(
        object, {"header", "pose", "id", "type", "primitives", "primitive_poses", "meshes", "mesh_poses", "planes",
                 "plane_poses", "subframe_names", "subframe_poses", "operation"});
    if (!other.empty()) doc.fail(other.front(), "not a field of a moveit_msgs/CollisionObject");
    const Field idField = doc.required(object, "id");
    const std::string id = doc.text(idField);
    if (id.empty()) doc.fail(idField, "an empty id");
    if (const auto [it, inserted] = idLines.emplace(id, idField.line); !inserted) {
      doc.fail(idField, "id " + yaml::quoted(id) + " appears twice (first at line " + std::to_string(it->second) + ")");
    }
    std::string frame;
    if (const Field header = doc.child(object, "header"); header.node.IsDefined() && !header.node.IsNull()) {
      if (const Field f = doc.child(header, "frame_id"); f.node.IsDefined()) frame = doc.text(f);
    }
    if (const Field planes = doc.child(object, "planes"); planes.node.IsDefined()) {
      doc.fail(planes, "planes are not supported (an infinite plane is not a mesh)");
    }
    const Pose objectPose = doc.pose(doc.child(object, "pose"));

    std::vector<Vec3> vertices;
    std::vector<TriangleIndices> triangles;
    readShapes(doc, object, "primitives", "primitive_poses", objectPose,
               [&](const Field& p) { return primitiveMesh(doc, p, id); }, vertices, triangles, &scene.primitives);
    readShapes(doc, object, "meshes", "mesh_poses", objectPose,
               [&](const Field& m) { return meshShape(doc, m, id); }, vertices, triangles);
    if (triangles.empty()) doc.fail(object, "object " + yaml::quoted(id) + " has no primitives and no meshes");
    scene.objects.emplace_back(std::move(vertices), std::move(triangles), id);
    scene.frames.push_back(frame);
    scene.lines.push_back(object.line);
  }
  return scene;
}

PlanningSceneYaml readPlanningSceneYaml(const std::string& path) {
  return parsePlanningSceneYaml(readInputFile(path, "scene file"), path);
}

}  // namespace adsd::planner
