#include "adsd/io/load_mesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <sstream>
#include <unordered_map>
#include <utility>
#include <vector>

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "adsd/error.h"
#include "child_process_reader.h"
#include "file_checks.h"
#include "polygon_soup.h"

namespace adsd::io {

namespace {

/// A node transform must be affine: assimp (and we) apply only its upper 3x4 part, so a bottom row
/// other than (0 0 0 1) would be silently ignored. Assimp stores matrices in float, and composes
/// some (COLLADA's transform stacks) itself, so allow float rounding: 1e-6, dimensionless.
constexpr double kAffineBottomRowTolerance = 1e-6;

using Affine = Eigen::Affine3d;

std::string oneLine(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

/// A name from the file, fit for a one-line message.
std::string quoted(const aiString& name) { return "'" + oneLine(name.C_Str()) + "'"; }


/// \p m as an affine map; \p what names the matrix in messages ("node 'arm'").
Affine toAffine(const aiMatrix4x4& m, const std::string& path, const std::string& what) {
  const double entries[4][4] = {{m.a1, m.a2, m.a3, m.a4},
                                {m.b1, m.b2, m.b3, m.b4},
                                {m.c1, m.c2, m.c3, m.c4},
                                {m.d1, m.d2, m.d3, m.d4}};
  Eigen::Matrix4d matrix;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) matrix(r, c) = entries[r][c];
  }
  if (!matrix.allFinite()) throw InputError(path + ": " + what + " has a non-finite transform entry");
  if ((matrix.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > kAffineBottomRowTolerance) {
    throw InputError(path + ": " + what + " has a projective transform (bottom row is not 0 0 0 1)");
  }
  Affine affine = Affine::Identity();
  affine.matrix().topRows<3>() = matrix.topRows<3>();
  return affine;
}

Affine toAffine(const aiMatrix4x4& m, const std::string& path, const aiNode& node) {
  return toAffine(m, path, "node " + quoted(node.mName));
}

/// Each node's frame in the root's (its transform composed with its ancestors'), by name: where
/// names repeat, the first in depth-first order, as assimp's own FindNode answers. Made once per
/// file that has bones, so that a hostile file's many bones cost one walk, not one each.
using NodePlacements = std::unordered_map<std::string, Affine>;

NodePlacements placeNodes(const aiScene& scene, const std::string& path) {
  NodePlacements placements;
  std::vector<std::pair<const aiNode*, Affine>> pending;
  pending.emplace_back(scene.mRootNode, toAffine(scene.mRootNode->mTransformation, path, *scene.mRootNode));
  while (!pending.empty()) {
    const auto [node, toRoot] = pending.back();
    pending.pop_back();
    placements.emplace(node->mName.C_Str(), toRoot);
    for (unsigned c = node->mNumChildren; c-- > 0;) {  // reversed: the first child is taken first
      const aiNode* child = node->mChildren[c];
      if (child != nullptr) pending.emplace_back(child, toRoot * toAffine(child->mTransformation, path, *child));
    }
  }
  return placements;
}

/// A skinned mesh's vertices where the file shows them at rest: each vertex at the weighted mean
/// of its bones' placements, bone b mapping mesh coordinates to the root by its node's transform
/// (with the node's ancestors) after its offset matrix, which assimp forms from the file's inverse
/// bind matrix and, for COLLADA, the bind shape matrix. The mesh's own node transform plays no
/// part, as in assimp's viewer and in COLLADA's skinning rule. A vertex no bone weighs stays at
/// its node's placement \p toRoot. Read unskinned, an outside review's skinned cube (assimp's
/// box_nested_animation.dae) stood 1.41 from a probe at its rest centre instead of 1.00.
std::vector<Vec3> skinnedVertices(const NodePlacements& nodes, const aiMesh& mesh, const Affine& toRoot,
                                  const std::string& path) {
  const std::string meshName = "mesh " + quoted(mesh.mName);
  std::vector<Vec3> sum(mesh.mNumVertices, Vec3::Zero());
  std::vector<double> weight(mesh.mNumVertices, 0.0);
  for (unsigned b = 0; b < mesh.mNumBones; ++b) {
    const aiBone& bone = *mesh.mBones[b];
    const std::string boneName = meshName + " bone " + quoted(bone.mName);
    const auto node = nodes.find(bone.mName.C_Str());
    if (node == nodes.end()) throw InputError(path + ": " + boneName + " names no node of the scene");
    const Affine placement = node->second * toAffine(bone.mOffsetMatrix, path, boneName + "'s offset matrix");
    for (unsigned w = 0; w < bone.mNumWeights; ++w) {
      const aiVertexWeight& vw = bone.mWeights[w];
      if (vw.mVertexId >= mesh.mNumVertices) {
        throw InputError(path + ": " + boneName + " weighs vertex " + std::to_string(vw.mVertexId) +
                         " but the mesh has " + std::to_string(mesh.mNumVertices) + " vertices");
      }
      if (!std::isfinite(vw.mWeight) || vw.mWeight < 0.0f) {
        throw InputError(path + ": " + boneName + " gives vertex " + std::to_string(vw.mVertexId) +
                         " the weight " + std::to_string(vw.mWeight) + " (weights are finite and >= 0)");
      }
      if (vw.mWeight == 0.0f) continue;
      const aiVector3D& p = mesh.mVertices[vw.mVertexId];
      sum[vw.mVertexId] += vw.mWeight * (placement * Vec3(p.x, p.y, p.z));
      weight[vw.mVertexId] += vw.mWeight;
    }
  }
  std::vector<Vec3> placed(mesh.mNumVertices);
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    // Weights that do not sum to 1 are normalized, as most exporters and viewers do.
    placed[v] = weight[v] > 0.0 ? Vec3(sum[v] / weight[v]) : Vec3(toRoot * Vec3(p.x, p.y, p.z));
  }
  return placed;
}

std::string formatPoint(const aiVector3D& p) {
  std::ostringstream out;
  out << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  return out.str();
}

/// Triangles gathered from the node tree, in the file's root frame.
using Gathered = detail::ReadTriangles;

/// Appends the triangles of \p mesh, placed by \p toRoot, to \p out. requireConsistentScene checked
/// the indices before post-processing; they are checked again here, after it, because reading out
/// of range would be a crash, not an error message.
void gatherMesh(const NodePlacements& nodes, const aiMesh& mesh, const Affine& toRoot, const std::string& path,
                Gathered& out) {
  const std::string meshName = "mesh " + quoted(mesh.mName);
  std::uint64_t triangleFaces = 0;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const unsigned n = mesh.mFaces[f].mNumIndices;
    if (n == 3) ++triangleFaces;
    else if (n == 2) ++out.lines;
    else if (n == 1) ++out.points;
  }
  if (triangleFaces == 0) return;  // a line or point set: dropped, as documented

  const std::uint64_t base = out.vertices.size();
  if (base + mesh.mNumVertices > std::numeric_limits<std::uint32_t>::max()) {
    throw InputError(path + ": more than 2^32 - 1 vertices");
  }
  const std::vector<Vec3> skinned =
      mesh.mNumBones > 0 ? skinnedVertices(nodes, mesh, toRoot, path) : std::vector<Vec3>();
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
    const aiVector3D& p = mesh.mVertices[v];
    const Vec3 world = skinned.empty() ? Vec3(toRoot * Vec3(p.x, p.y, p.z)) : skinned[v];
    if (!world.allFinite()) {
      const char* after = skinned.empty() ? " after its node transform" : " after skinning";
      throw InputError(path + ": " + meshName + " has a vertex with a non-finite coordinate " + formatPoint(p) +
                       (Vec3(p.x, p.y, p.z).allFinite() ? after : ""));
    }
    out.vertices.push_back(world);
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;
    TriangleIndices triangle;
    for (int k = 0; k < 3; ++k) {
      if (face.mIndices[k] >= mesh.mNumVertices) {
        throw InputError(path + ": " + meshName + " face " + std::to_string(f) + " refers to vertex " +
                         std::to_string(face.mIndices[k]) + " but the mesh has " +
                         std::to_string(mesh.mNumVertices) + " vertices");
      }
      triangle[k] = static_cast<std::uint32_t>(base + face.mIndices[k]);
    }
    out.triangles.push_back(triangle);
  }
}

/// Walks the node tree with an explicit stack (a deep tree from a hostile file must not overflow
/// the call stack), composing transforms from the root down: p_root = T_root ... T_parent T_node p.
/// A mesh referenced by several nodes is placed once per reference, as the scene shows it.
Gathered gatherScene(const aiScene& scene, const std::string& path) {
  Gathered out;
  const bool skinned = std::any_of(scene.mMeshes, scene.mMeshes + scene.mNumMeshes,
                                   [](const aiMesh* m) { return m != nullptr && m->mNumBones > 0; });
  const NodePlacements nodes = skinned ? placeNodes(scene, path) : NodePlacements();
  std::vector<std::pair<const aiNode*, Affine>> pending;
  pending.emplace_back(scene.mRootNode, toAffine(scene.mRootNode->mTransformation, path, *scene.mRootNode));
  while (!pending.empty()) {
    const auto [node, toRoot] = pending.back();
    pending.pop_back();
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
      const unsigned m = node->mMeshes[i];
      if (m >= scene.mNumMeshes || scene.mMeshes[m] == nullptr) {
        throw InputError(path + ": node " + quoted(node->mName) + " refers to mesh " +
                         std::to_string(m) + " which does not exist");
      }
      gatherMesh(nodes, *scene.mMeshes[m], toRoot, path, out);
    }
    for (unsigned c = 0; c < node->mNumChildren; ++c) {
      const aiNode* child = node->mChildren[c];
      if (child == nullptr) continue;
      pending.emplace_back(child, toRoot * toAffine(child->mTransformation, path, *child));
    }
  }
  return out;
}

/// The scene as the loader left it must be safe for the post-processing steps to read: arrays
/// present where counts say so, face indices and bone weights inside their mesh. We check this
/// ourselves instead of running assimp's ValidateDataStructure, which also rejects files over
/// things that do not matter here (an empty extra solid in an STL, animation or material details).
void requireConsistentScene(const aiScene& scene, const std::string& path) {
  if (scene.mNumMeshes > 0 && scene.mMeshes == nullptr) throw InputError(path + ": the scene's mesh list is missing");
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* mesh = scene.mMeshes[m];
    if (mesh == nullptr) throw InputError(path + ": mesh " + std::to_string(m) + " is missing");
    const std::string meshName = "mesh " + quoted(mesh->mName);
    if ((mesh->mNumVertices > 0 && mesh->mVertices == nullptr) || (mesh->mNumFaces > 0 && mesh->mFaces == nullptr)) {
      throw InputError(path + ": " + meshName + " lacks the vertices or faces it declares");
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices > 0 && face.mIndices == nullptr) {
        throw InputError(path + ": " + meshName + " face " + std::to_string(f) + " lacks its indices");
      }
      for (unsigned k = 0; k < face.mNumIndices; ++k) {
        if (face.mIndices[k] >= mesh->mNumVertices) {
          throw InputError(path + ": " + meshName + " face " + std::to_string(f) + " refers to vertex " +
                           std::to_string(face.mIndices[k]) + " but the mesh has " +
                           std::to_string(mesh->mNumVertices) + " vertices");
        }
      }
    }
    // Before post-processing: JoinIdenticalVertices takes a vertex with a NaN coordinate for a
    // copy of an earlier vertex (every comparison with NaN is false, so "different" is never
    // found) and replaces it, which would load the file as a degenerate triangle, no error.
    const bool hasSurface = std::any_of(mesh->mFaces, mesh->mFaces + mesh->mNumFaces,
                                        [](const aiFace& face) { return face.mNumIndices >= 3; });
    for (unsigned v = 0; hasSurface && v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      if (!Vec3(p.x, p.y, p.z).allFinite()) {
        throw InputError(path + ": " + meshName + " has a vertex with a non-finite coordinate " + formatPoint(p));
      }
    }
    if (mesh->mNumBones > 0 && mesh->mBones == nullptr) throw InputError(path + ": " + meshName + " lacks its bones");
    for (unsigned b = 0; b < mesh->mNumBones; ++b) {
      const aiBone* bone = mesh->mBones[b];
      if (bone == nullptr || (bone->mNumWeights > 0 && bone->mWeights == nullptr)) {
        throw InputError(path + ": " + meshName + " bone " + std::to_string(b) + " is incomplete");
      }
      for (unsigned w = 0; w < bone->mNumWeights; ++w) {
        if (bone->mWeights[w].mVertexId >= mesh->mNumVertices) {
          throw InputError(path + ": " + meshName + " bone " + std::to_string(b) + " weighs vertex " +
                           std::to_string(bone->mWeights[w].mVertexId) + " but the mesh has " +
                           std::to_string(mesh->mNumVertices) + " vertices");
        }
      }
    }
    if (mesh->mNumAnimMeshes > 0 && mesh->mAnimMeshes == nullptr) {
      throw InputError(path + ": " + meshName + " lacks its animation meshes");
    }
    for (unsigned a = 0; a < mesh->mNumAnimMeshes; ++a) {
      const aiAnimMesh* anim = mesh->mAnimMeshes[a];
      if (anim == nullptr || anim->mNumVertices != mesh->mNumVertices) {
        throw InputError(path + ": " + meshName + " animation mesh " + std::to_string(a) +
                         " does not match the mesh's vertex count");
      }
    }
  }
}

/// Removes meshes without faces or vertices (an STL may hold an empty extra solid), which
/// SortByPType would reject as having no primitive type, and the references nodes hold to them.
/// The scene belongs to the importer; post-processing edits it in place the same way.
void dropEmptyMeshes(aiScene& scene) {
  std::vector<long long> newIndex(scene.mNumMeshes, -1);
  unsigned kept = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    aiMesh* mesh = scene.mMeshes[m];
    if (mesh->mNumFaces > 0 && mesh->mNumVertices > 0) {
      newIndex[m] = kept;
      scene.mMeshes[kept++] = mesh;
    } else {
      delete mesh;
    }
  }
  if (kept == scene.mNumMeshes) return;
  scene.mNumMeshes = kept;
  std::vector<aiNode*> pending{scene.mRootNode};
  while (!pending.empty()) {
    aiNode* node = pending.back();
    pending.pop_back();
    if (node == nullptr) continue;
    unsigned keptRefs = 0;
    for (unsigned i = 0; i < node->mNumMeshes; ++i) {
      const unsigned m = node->mMeshes[i];
      if (m < newIndex.size() && newIndex[m] >= 0) node->mMeshes[keptRefs++] = static_cast<unsigned>(newIndex[m]);
    }
    node->mNumMeshes = keptRefs;
    for (unsigned c = 0; c < node->mNumChildren; ++c) pending.push_back(node->mChildren[c]);
  }
}

/// Faces with at least three corners in the scene as the loader produced it, before
/// post-processing.
std::uint64_t countSurfaceFaces(const aiScene& scene, std::uint64_t& lines, std::uint64_t& points) {
  std::uint64_t surfaces = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh* mesh = scene.mMeshes == nullptr ? nullptr : scene.mMeshes[m];
    if (mesh == nullptr || mesh->mFaces == nullptr) continue;
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const unsigned n = mesh->mFaces[f].mNumIndices;
      if (n >= 3) ++surfaces;
      else if (n == 2) ++lines;
      else if (n == 1) ++points;
    }
  }
  return surfaces;
}

[[noreturn]] void throwNoTriangles(const std::string& path, std::uint64_t lines, std::uint64_t points) {
  std::string what = path + ": the file holds no triangles";
  if (lines + points > 0) {
    what += " (only " + std::to_string(lines) + " lines and " + std::to_string(points) +
            " points, which are not surfaces)";
  }
  throw InputError(what);
}

/// Some of assimp's readers (ASE, CSM) answered a file they cannot make sense of with a placeholder
/// instead of an error: "hello world" saved as .ase came back as 8 triangles on one point, the
/// skeleton mesh that readWithAssimp now turns off. Any placeholder of that shape left is refused:
/// no file that describes a surface gives it. Our own readers, which invent nothing, accept a file
/// that is a single point.
void requireMoreThanOnePoint(const Gathered& gathered, const std::string& path) {
  const Vec3& first = gathered.vertices[gathered.triangles.front()[0]];
  for (const TriangleIndices& t : gathered.triangles) {
    for (const std::uint32_t v : t) {
      if (gathered.vertices[v] != first) return;
    }
  }
  std::ostringstream where;
  where << '(' << first.x() << ", " << first.y() << ", " << first.z() << ')';
  throw InputError(path + ": assimp made nothing of the file but " + std::to_string(gathered.triangles.size()) +
                   " triangles on the single point " + where.str() + ", not a surface (is it a mesh file?)");
}

/// Assimp's part of loading: parse, post-process and gather the triangles in double. Runs in the
/// child process of readInChildProcess, so its InputErrors travel back as messages.
Gathered readWithAssimp(const std::string& path, ColladaUpAxis up) {
  Assimp::Importer importer;
  // Assimp turns a COLLADA file's up axis to +y by a rotation it puts into the root node's
  // transform; asWritten leaves it out (its <unit> scale, in the same transform, stays, as RViz
  // applies it).
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, up == ColladaUpAxis::asWritten);
  // A file without geometry (a COLLADA scene of bare nodes, a BVH motion, an instance naming no
  // geometry) is otherwise given a mesh assimp invents to show the node skeleton, which would
  // then stand in for the robot or obstacle without a word.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_NO_SKELETON_MESHES, true);
  const aiScene* scene = importer.ReadFile(path, 0);
  if (scene == nullptr) {
    const std::string error = oneLine(importer.GetErrorString());
    // Assimp catches the allocation failure itself; thrown again, it is reported with the limit.
    if (error.find("bad_alloc") != std::string::npos) throw std::bad_alloc();
    throw InputError(path + ": cannot be parsed: " + error);
  }
  requireConsistentScene(*scene, path);
  std::uint64_t lines = 0, points = 0;
  if (countSurfaceFaces(*scene, lines, points) == 0) throwNoTriangles(path, lines, points);
  dropEmptyMeshes(const_cast<aiScene&>(*scene));

  // Triangulate turns polygons into triangles; JoinIdenticalVertices shares corners (loaders emit
  // three vertices per face); SortByPType splits mixed meshes so that lines and points land in
  // meshes of their own, which gatherMesh drops. Node transforms are applied by our own walk, in double precision, rather than by
  // PreTransformVertices, which composes them in assimp's float and loses the node names our error
  // messages use. Assimp's defaults for COLLADA <unit> and <up_axis> stay on unless the caller reads
  // as written (ColladaUpAxis): that is the frame OMPL.app's assimp loading sees too, and problem
  // files written for it must mean the same to us.
  const unsigned steps = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType;
  scene = importer.ApplyPostProcessing(steps);
  if (scene == nullptr) {
    throw InputError(path + ": cannot be parsed: " + oneLine(importer.GetErrorString()));
  }
  if (scene->mRootNode == nullptr) throw InputError(path + ": the file holds no scene nodes");
  return gatherScene(*scene, path);
}

Mesh loadMeshUnguarded(const std::string& path, const ReaderLimits& limits, ColladaUpAxis up) {
  std::uint64_t fileBytes = 0;
  {
    const std::string bytes = detail::readWholeFile(path);
    fileBytes = bytes.size();
    const detail::MeshReader reader = detail::chooseReader(path, bytes);
    // Assimp 5.2 reads no UTF-16 file either (its own test models: "malformed XML", "magic
    // sequence not found", or no triangles).
    detail::requireNarrowText(path, bytes, reader);
    // OBJ, OFF, PLY and STL are read into double without loss (see each reader for why it, and
    // docs/numerics.md for the measurement); everything else goes through assimp, in float.
    switch (reader) {
      case detail::MeshReader::obj: return detail::meshFromSoup(detail::readObj(path, bytes), path);
      case detail::MeshReader::off: return detail::meshFromSoup(detail::readOff(path, bytes), path);
      case detail::MeshReader::ply: return detail::meshFromSoup(detail::readPly(path, bytes), path);
      case detail::MeshReader::stl:
        detail::requireCompleteBinaryStl(path, bytes, bytes.size());
        return detail::meshFromSoup(detail::readStl(path, bytes), path);
      case detail::MeshReader::assimp: break;
    }
    // Assimp reads COLLADA by content whatever the file's name, so the check goes by content too.
    // The checks stay although assimp runs in a child process: they name the element at fault,
    // where the child's end could only say that assimp crashed or ran out of time.
    detail::checkZippedCollada(path, bytes);
    if (detail::readAsCollada(path, bytes)) detail::requireIntegerIndexLists(path, bytes);
  }  // the bytes are freed before assimp reads the file itself (it may need files beside it)

  Gathered gathered = detail::readInChildProcess(path, [&] { return readWithAssimp(path, up); },
                                                 detail::effectiveLimits(limits, fileBytes));
  if (gathered.triangles.empty()) throwNoTriangles(path, gathered.lines, gathered.points);
  requireMoreThanOnePoint(gathered, path);
  detail::dropRepeatedTriangles(gathered.triangles, gathered.vertices.size());
  return Mesh(std::move(gathered.vertices), std::move(gathered.triangles), path);
}

}  // namespace

Mesh loadMesh(const std::string& path, const ReaderLimits& limits, ColladaUpAxis up) {
  try {
    return loadMeshUnguarded(path, limits, up);
  } catch (const std::bad_alloc&) {
    throw InputError(path + ": out of memory while loading the mesh");
  }
}

}  // namespace adsd::io
