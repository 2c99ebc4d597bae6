#pragma once
/// \file
/// \brief The shipped problems' scenes in memory (the same meshes the build writes for the cfgs),
/// with state spaces bounded like their cfgs, and seeded random states for them.

#include <memory>
#include <random>
#include <string>
#include <vector>

#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/SE2StateSpace.h>
#include <ompl/base/spaces/SE3StateSpace.h>

#include "adsd/planner/rigid_body_scene.h"
#include "adsd/planner/state_pose.h"
#include "adsd/problem_scenes.h"

namespace adsd::planner::test {

/// \brief A scene plus a space information whose bounds are the cfg's volume.
struct SceneFixture {
  std::string name;
  std::shared_ptr<RigidBodyScene> scene;
  ompl::base::SpaceInformationPtr si;
  Eigen::AlignedBox3d volume;
  /// The environment as generated, unsplit, for the oracle: it places the robot's triangles once
  /// per call, so one call over the whole mesh is much cheaper than one per part.
  std::vector<Mesh> oracleEnvironment;
};

inline SceneFixture makeFixture(const shapes::ProblemScene& generated, RigidBodySpace space,
                                const Eigen::AlignedBox3d& volume) {
  SceneFixture f;
  f.name = generated.name;
  f.scene = std::make_shared<RigidBodyScene>();
  f.scene->robot = generated.robot;
  // Split as PlanningProblem splits a loaded world, so the broad phase is exercised as in use.
  f.scene->environment = splitForRobot(generated.environment, generated.robot);
  f.oracleEnvironment = {generated.environment};
  f.scene->space = space;
  f.volume = volume;
  const int dims = space == RigidBodySpace::se2 ? 2 : 3;
  ompl::base::RealVectorBounds bounds(dims);
  for (int i = 0; i < dims; ++i) {
    bounds.setLow(i, volume.min()[i]);
    bounds.setHigh(i, volume.max()[i]);
  }
  ompl::base::StateSpacePtr ss;
  if (space == RigidBodySpace::se2) {
    auto se2 = std::make_shared<ompl::base::SE2StateSpace>();
    se2->setBounds(bounds);
    ss = se2;
  } else {
    auto se3 = std::make_shared<ompl::base::SE3StateSpace>();
    se3->setBounds(bounds);
    ss = se3;
  }
  f.si = std::make_shared<ompl::base::SpaceInformation>(ss);
  return f;
}

/// The volumes of problems/*.cfg (z of SE(2) volumes unused).
inline SceneFixture officeFixture() {
  return makeFixture(shapes::officeScene(), RigidBodySpace::se2, {Vec3(-10, -6, 0), Vec3(10, 6, 0)});
}
inline SceneFixture mazeFixture() {
  return makeFixture(shapes::mazeScene(), RigidBodySpace::se2, {Vec3(-4.8, -4.8, 0), Vec3(4.8, 4.8, 0)});
}
inline SceneFixture thinWallFixture() {
  return makeFixture(shapes::thinWallScene(), RigidBodySpace::se2, {Vec3(-4, -4, 0), Vec3(4, 4, 0)});
}
inline SceneFixture bugTrapFixture() {
  return makeFixture(shapes::bugTrapScene(), RigidBodySpace::se3, {Vec3(-3, -3, -3), Vec3(6, 3, 3)});
}
inline SceneFixture twistedPassageFixture() {
  return makeFixture(shapes::twistedPassageScene(), RigidBodySpace::se3, {Vec3(-4.5, -1.8, -1.8), Vec3(4.5, 1.8, 1.8)});
}
inline SceneFixture alphaPuzzleFixture() {
  return makeFixture(shapes::alphaPuzzleScene(), RigidBodySpace::se3, {Vec3(-3.5, -3.5, -3), Vec3(3.5, 3.5, 4.5)});
}

/// \brief Seeded random robot poses within the volume: half uniform, half placed near a random
/// environment vertex (within the robot's radius), so that near-contact states and collisions are
/// common. Deterministic for a seed on one platform.
class PoseSampler {
 public:
  PoseSampler(const SceneFixture& f, std::uint64_t seed) : f_(f), random_(seed) {}

  Pose next() {
    const bool nearSurface = (count_++ % 2) == 1;
    Vec3 position;
    if (nearSurface) {
      const Mesh& env = f_.scene->environment[pick(f_.scene->environment.size())];
      const Vec3& v = env.vertices()[pick(env.vertices().size())];
      const double reach = robotRadius(*f_.scene);
      position = v + reach * Vec3(unit() * 2 - 1, unit() * 2 - 1, unit() * 2 - 1);
      for (int i = 0; i < 3; ++i) {
        position[i] = std::min(std::max(position[i], f_.volume.min()[i]), f_.volume.max()[i]);
      }
    } else {
      for (int i = 0; i < 3; ++i) position[i] = f_.volume.min()[i] + unit() * (f_.volume.max()[i] - f_.volume.min()[i]);
    }
    Pose pose = Pose::Identity();
    if (f_.scene->space == RigidBodySpace::se2) {
      pose.translate(Vec3(position.x(), position.y(), 0));
      pose.rotate(Eigen::AngleAxisd((unit() * 2 - 1) * M_PI, Vec3::UnitZ()));
    } else {
      pose.translate(position);
      // Uniform rotation from a normalized 4D Gaussian.
      std::normal_distribution<double> gauss;
      Eigen::Quaterniond q(gauss(random_), gauss(random_), gauss(random_), gauss(random_));
      pose.rotate(q.normalized().toRotationMatrix());
    }
    return pose;
  }

 private:
  double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(random_); }
  std::size_t pick(std::size_t n) { return static_cast<std::size_t>(unit() * n) % n; }

  const SceneFixture& f_;
  std::mt19937_64 random_;
  int count_ = 0;
};

}  // namespace adsd::planner::test
