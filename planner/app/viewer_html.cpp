#include "viewer_html.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <vector>

#include <ompl/base/ScopedState.h>

#include "adsd/distance.h"
#include "adsd/error.h"
#include "adsd/planner/state_pose.h"

namespace adsd::app {

namespace viewer_assets {
// Written at build time by embed_viewer_assets.cmake from viewer/viewer.html and the npm package
// `three` (viewer/package-lock.json pins its version).
extern const char kViewerTemplate[];
extern const char kThreeCore[];
extern const char kThreeModule[];
extern const char kOrbitControls[];
}  // namespace viewer_assets

namespace {

using planner::RigidBodyScene;

/// Witness search slack, relative to the scene's length scale (dimensionless): a mesh pair whose
/// distance is within this of the checker's clearance realizes it. Ten times the core's promised
/// accuracy (1e-10 of the scene's diagonal, adsd/distance.h), so rounding cannot hide the pair.
constexpr double kWitnessSlackPerScale = 1e-9;

std::string base64(const std::vector<std::uint8_t>& bytes) {
  static const char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = static_cast<std::uint32_t>(bytes[i]) << 16;
    if (n > 1) v |= static_cast<std::uint32_t>(bytes[i + 1]) << 8;
    if (n > 2) v |= bytes[i + 2];
    out += kDigits[(v >> 18) & 63];
    out += kDigits[(v >> 12) & 63];
    out += n > 1 ? kDigits[(v >> 6) & 63] : '=';
    out += n > 2 ? kDigits[v & 63] : '=';
  }
  return out;
}

/// Little-endian, as the page's Float32Array and Uint32Array read them on every browser's platform.
void appendLittleEndian(std::vector<std::uint8_t>& bytes, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) bytes.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
}

/// The meshes of \p parts as one, for drawing: float32 positions and uint32 indices, base64.
std::string meshJson(const std::vector<Mesh>& parts) {
  std::vector<std::uint8_t> positions, indices;
  std::uint32_t offset = 0;
  for (const Mesh& m : parts) {
    for (const Vec3& v : m.vertices()) {
      for (int k = 0; k < 3; ++k) {
        const float f = static_cast<float>(v[k]);
        std::uint32_t bits;
        std::memcpy(&bits, &f, sizeof bits);
        appendLittleEndian(positions, bits);
      }
    }
    for (const TriangleIndices& t : m.triangles()) {
      for (const std::uint32_t i : t) appendLittleEndian(indices, offset + i);
    }
    offset += static_cast<std::uint32_t>(m.vertices().size());
  }
  return "{\"positions\":\"" + base64(positions) + "\",\"indices\":\"" + base64(indices) + "\"}";
}

/// A JSON string; '<' is escaped so that no text can close the page's <script> element.
std::string jsonString(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || c == '<' || c == '>' || c == '&') {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", u);
      out += buffer;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string htmlText(std::string_view s) {
  std::string out;
  for (const char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

/// Shortest text that reads back as the same double; every value here is finite (poses of valid
/// states, distances between mesh points), and a non-finite one is our bug.
void appendNumber(std::string& out, double x) {
  if (!std::isfinite(x)) throw std::logic_error("viewer: a non-finite number in the page's data");
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  out += buffer;
}

void appendArray(std::string& out, std::initializer_list<double> values) {
  out += '[';
  bool first = true;
  for (const double v : values) {
    if (!first) out += ',';
    first = false;
    appendNumber(out, v);
  }
  out += ']';
}

/// [x, y, z, qx, qy, qz, qw]: the order of three.js's position and quaternion.
void appendPose(std::string& out, const Pose& pose) {
  const Eigen::Quaterniond q(pose.rotation());
  const Vec3 t = pose.translation();
  appendArray(out, {t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w()});
}

/// The closest pair of points between the robot at \p pose and the environment (world frame):
/// the mesh pair whose distance is the clearance \p clearance, found by queries capped just above
/// it, which stop at the hull bounds for the far pairs. Should the checker's value be another
/// engine's (FCL's), the exact minimum over all pairs is taken instead.
std::pair<Vec3, Vec3> witnesses(const RigidBodyScene& scene, const Pose& pose, double clearance, double slack,
                                DistanceScratch& scratch) {
  double cap = clearance + slack;
  for (int pass = 0; pass < 2; ++pass) {
    bool found = false;
    std::pair<Vec3, Vec3> best{pose.translation(), pose.translation()};
    for (const Mesh& r : scene.robot) {
      for (const Mesh& e : scene.environment) {
        const DistanceResult d = distance(r, pose, e, Pose::Identity(),
                                          std::isfinite(cap) ? DistanceOptions::cappedAt(cap) : DistanceOptions::exactDistance(),
                                          scratch);
        if (d.status == DistanceStatus::beyondCap) continue;
        if (!found || d.distance < cap) {
          cap = d.distance;
          best = {d.witnessA, d.witnessB};
          found = true;
        }
        if (cap <= 0.0) return best;  // touching: nothing is closer, and a cap must be positive
      }
    }
    if (found) return best;
    cap = std::numeric_limits<double>::infinity();
  }
  throw std::logic_error("viewer: no mesh pair between robot and environment");
}

/// The template with each marker replaced by its text. Every marker must be there exactly once;
/// markers are found in the template only, never in the texts put in (a problem named like one).
std::string fillTemplate(std::string_view page, std::vector<std::pair<std::string_view, std::string_view>> fills) {
  std::vector<std::pair<std::size_t, std::size_t>> at;  // (position in the template, fill)
  for (std::size_t f = 0; f < fills.size(); ++f) {
    const std::string_view marker = fills[f].first;
    const std::size_t p = page.find(marker);
    if (p == std::string_view::npos || page.find(marker, p + 1) != std::string_view::npos) {
      throw std::logic_error("viewer template: marker " + std::string(marker) + " is not there exactly once");
    }
    at.emplace_back(p, f);
  }
  std::sort(at.begin(), at.end());
  std::string out;
  std::size_t from = 0;
  for (const auto& [p, f] : at) {
    out.append(page.substr(from, p - from));
    out.append(fills[f].second);
    from = p + fills[f].first.size();
  }
  out.append(page.substr(from));
  return out;
}

}  // namespace

ViewerSummary writeViewerHtml(const std::string& file, const planner::ProblemFile& problemFile,
                              const planner::PlanningProblem& problem, const ompl::geometric::PathGeometric* path,
                              const std::string& source) {
  const RigidBodyScene& scene = problem.scene();
  const ompl::base::SpaceInformationPtr& si = problem.spaceInformation();

  // The states shown: the path as measurePath() samples it, or the start and the goal.
  ompl::geometric::PathGeometric states(si);
  if (path != nullptr) {
    states = *path;
    states.interpolate();
  } else {
    ompl::base::ScopedState<> start(si->getStateSpace()), goal(si->getStateSpace());
    planner::poseToState(problemFile.start.toPose(), scene.space, start.get());
    planner::poseToState(problemFile.goal.toPose(), scene.space, goal.get());
    states.append(start.get());
    states.append(goal.get());
  }

  // Each part gets its sub-mesh tree once, as the checker's own copy does (mesh_validity_checker.cpp).
  RigidBodyScene prepared = scene;
  for (Mesh& m : prepared.robot) m.buildHierarchy();
  for (Mesh& m : prepared.environment) m.buildHierarchy();
  const double slack = kWitnessSlackPerScale * planner::sceneScale(scene);
  DistanceScratch scratch;

  ViewerSummary summary;
  summary.states = states.getStateCount();
  summary.minClearance = std::numeric_limits<double>::infinity();
  std::string poses = "[", clearances = "[", witnessPairs = "[";
  for (std::size_t i = 0; i < states.getStateCount(); ++i) {
    const ompl::base::State* s = states.getState(i);
    const Pose pose = planner::poseFromState(s, scene.space);
    const double c = problem.checker()->clearance(s);
    summary.minClearance = std::min(summary.minClearance, c);
    const auto [onRobot, onEnvironment] = witnesses(prepared, pose, c, slack, scratch);
    if (i > 0) poses += ',', clearances += ',', witnessPairs += ',';
    appendPose(poses, pose);
    appendNumber(clearances, c);
    appendArray(witnessPairs, {onRobot.x(), onRobot.y(), onRobot.z(), onEnvironment.x(), onEnvironment.y(),
                               onEnvironment.z()});
  }
  poses += ']', clearances += ']', witnessPairs += ']';

  std::string data = "{\"name\":" + jsonString(problemFile.name) +
                     ",\"space\":" + jsonString(scene.space == planner::RigidBodySpace::se2 ? "SE(2)" : "SE(3)") +
                     ",\"source\":" + jsonString(source) + ",\"environment\":" + meshJson(scene.environment) +
                     ",\"robot\":" + meshJson(scene.robot) + ",\"start\":";
  appendPose(data, problemFile.start.toPose());
  data += ",\"goal\":";
  appendPose(data, problemFile.goal.toPose());
  data += ",\"states\":" + poses + ",\"clearance\":" + clearances + ",\"witnesses\":" + witnessPairs + "}";

  const std::string title = htmlText(problemFile.name);
  const std::string page = fillTemplate(viewer_assets::kViewerTemplate,
                                        {{"@ADSD_TITLE@", title},
                                         {"@ADSD_DATA@", data},
                                         {"@ADSD_THREE_CORE@", viewer_assets::kThreeCore},
                                         {"@ADSD_THREE_MODULE@", viewer_assets::kThreeModule},
                                         {"@ADSD_ORBIT_CONTROLS@", viewer_assets::kOrbitControls}});
  summary.bytes = page.size();

  const std::string temporary = file + ".partial";
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw InputError(file + ": cannot write the viewer page");
    out << page;
    out.flush();
    if (!out) {
      out.close();
      std::remove(temporary.c_str());
      throw InputError(file + ": writing the viewer page failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, file, ec);
  if (ec) {
    std::remove(temporary.c_str());
    throw InputError(file + ": cannot rename the finished viewer page into place: " + ec.message());
  }
  return summary;
}

}  // namespace adsd::app
