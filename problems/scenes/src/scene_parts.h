#pragma once
/// \file
/// \brief Building blocks shared by the scene files: placed boxes, collected into one mesh.

#include <vector>

#include "adsd/mesh.h"
#include "adsd/shapes.h"

namespace adsd::shapes {

/// \brief Parts and their placements, merged into one environment mesh at the end.
class SceneParts {
 public:
  void add(const Mesh& part, const Pose& pose = Pose::Identity()) {
    parts_.push_back(part);
    poses_.push_back(pose);
  }
  /// An axis-aligned box spanning [lo, hi].
  void addBox(const Vec3& lo, const Vec3& hi, const Pose& frame = Pose::Identity()) {
    Pose pose = frame;
    pose.translate(0.5 * (lo + hi));
    add(box(0.5 * (hi - lo)), pose);
  }
  Mesh merged() const { return merge(parts_, poses_); }

 private:
  std::vector<Mesh> parts_;
  std::vector<Pose> poses_;
};

}  // namespace adsd::shapes
