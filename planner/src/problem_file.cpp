#include "adsd/planner/problem_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/parsers.hpp>

#include "adsd/error.h"
#include "adsd/planner/planner_registry.h"

namespace adsd::planner {

namespace {

namespace po = boost::program_options;
namespace fs = std::filesystem;

/// One `key = value` line after Boost has parsed the file, with its line number.
struct Entry {
  std::string key;  ///< "section.key"
  std::string value;
  int line = 0;
};

/// One `[section]` header.
struct SectionHeader {
  std::string name;
  int line = 0;
};

std::string trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  const auto end = s.find_last_not_of(" \t\r\n");
  return s.substr(begin, end - begin + 1);
}

/// Locates every key and section header by line, following the rules of Boost's config-file
/// parser (`#` starts a comment anywhere; blank lines skipped; `[name]` sets the prefix of the
/// keys after it; `key = value` with whitespace trimmed). Boost reads the values; this pass gives
/// messages their line numbers and finds the line Boost stumbled on.
void scanLines(const std::string& text, const std::string& source, std::vector<Entry>& entries,
               std::vector<SectionHeader>& sections) {
  std::istringstream in(text);
  std::string raw;
  std::string prefix;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string s = trim(raw.substr(0, raw.find('#')));
    if (s.empty()) continue;
    if (s.front() == '[') {
      if (s.back() != ']' || s.size() < 3) {
        throw InputError(source + ":" + std::to_string(line) + ": malformed section header '" + s + "'");
      }
      const std::string name = trim(s.substr(1, s.size() - 2));
      sections.push_back({name, line});
      prefix = name + ".";
      continue;
    }
    const auto eq = s.find('=');
    if (eq == std::string::npos || trim(s.substr(0, eq)).empty()) {
      throw InputError(source + ":" + std::to_string(line) + ": expected 'key = value', a [section] or a comment, got '" +
                       s + "'");
    }
    entries.push_back({prefix + trim(s.substr(0, eq)), trim(s.substr(eq + 1)), line});
  }
}

/// Reads the file with Boost.Program_options' config-file parser (as OMPL.app does, so a file
/// means the same to both), taking every key as unregistered, in file order.
std::vector<Entry> parseWithBoost(const std::string& text, const std::string& source,
                                  const std::vector<Entry>& located) {
  std::istringstream in(text);
  po::parsed_options parsed(nullptr);
  try {
    po::options_description none;
    parsed = po::parse_config_file(in, none, /*allow_unregistered=*/true);
  } catch (const std::exception& e) {
    throw InputError(source + ": cannot parse: " + e.what());
  }
  std::vector<Entry> entries;
  for (const po::option& option : parsed.options) {
    Entry entry;
    entry.key = option.string_key;
    entry.value = option.value.empty() ? std::string() : option.value.front();
    entries.push_back(entry);
  }
  // Both passes read the same lines in the same order; the scan contributes the line numbers.
  if (entries.size() == located.size()) {
    for (std::size_t i = 0; i < entries.size(); ++i) entries[i].line = located[i].line;
  }
  return entries;
}

SourceLocation locate(const std::string& source, const Entry& e) { return {source, e.line, e.key}; }

double parseNumber(const Entry& e, const std::string& source) {
  const std::string& v = e.value;
  if (v.empty()) throw InputError(locate(source, e).describe() + ": expected a number, the value is empty");
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(v.c_str(), &end);
  if (end != v.c_str() + v.size()) {
    throw InputError(locate(source, e).describe() + ": expected a number, got '" + v + "'");
  }
  if (!std::isfinite(x) || errno == ERANGE) {
    throw InputError(locate(source, e).describe() + ": expected a finite number, got '" + v + "'");
  }
  return x;
}

int parsePositiveInt(const Entry& e, const std::string& source) {
  const double x = parseNumber(e, source);
  if (x != std::floor(x) || x < 1 || x > 1e9) {
    throw InputError(locate(source, e).describe() + ": expected a positive whole number, got '" + e.value + "'");
  }
  return static_cast<int>(x);
}

double parsePositive(const Entry& e, const std::string& source) {
  const double x = parseNumber(e, source);
  if (!(x > 0.0)) throw InputError(locate(source, e).describe() + ": expected a number > 0, got '" + e.value + "'");
  return x;
}

bool parseFlag(const Entry& e, const std::string& source) {
  std::string v = e.value;
  std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return std::tolower(c); });
  if (v == "1" || v == "true" || v == "yes" || v == "on") return true;
  if (v == "0" || v == "false" || v == "no" || v == "off") return false;
  throw InputError(locate(source, e).describe() + ": expected 0 or 1, got '" + e.value + "'");
}

std::string resolvePath(const std::string& value, const std::string& directory) {
  const fs::path p(value);
  if (p.is_absolute() || directory.empty()) return p.lexically_normal().string();
  return (fs::path(directory) / p).lexically_normal().string();
}

/// The [problem] keys, each at most once.
class ProblemKeys {
 public:
  ProblemKeys(std::string source, int sectionLine) : source_(std::move(source)), sectionLine_(sectionLine) {}

  void add(const Entry& e) {
    const auto [it, inserted] = keys_.emplace(e.key, e);
    if (!inserted) {
      throw InputError(locate(source_, e).describe() + ": repeated (first at line " + std::to_string(it->second.line) +
                       ")");
    }
  }
  bool has(const std::string& key) const { return keys_.count("problem." + key) != 0; }
  const Entry& get(const std::string& key) const {
    const auto it = keys_.find("problem." + key);
    if (it == keys_.end()) {
      throw InputError(source_ + ":" + std::to_string(sectionLine_) + ": key 'problem." + key +
                       "' is missing from the [problem] section");
    }
    return it->second;
  }
  double number(const std::string& key) const { return parseNumber(get(key), source_); }

 private:
  std::string source_;
  int sectionLine_;
  std::map<std::string, Entry> keys_;
};

ProblemPose readPose(const ProblemKeys& keys, const std::string& which, RigidBodySpace space,
                     const std::string& source) {
  ProblemPose pose;
  pose.location = locate(source, keys.get(which + ".x"));
  pose.position.x() = keys.number(which + ".x");
  pose.position.y() = keys.number(which + ".y");
  pose.theta = keys.number(which + ".theta");
  if (space == RigidBodySpace::se3) {
    pose.position.z() = keys.number(which + ".z");
    pose.axis = Vec3(keys.number(which + ".axis.x"), keys.number(which + ".axis.y"), keys.number(which + ".axis.z"));
    if (pose.axis.norm() == 0.0 && pose.theta != 0.0) {
      throw InputError(locate(source, keys.get(which + ".axis.x")).describe() +
                       ": the rotation axis is zero but the angle is not");
    }
  }
  return pose;
}

const std::set<std::string>& se3OnlyPoseKeys() {
  static const std::set<std::string> keys = {"z", "axis.x", "axis.y", "axis.z"};
  return keys;
}

void readProblemSection(const std::vector<Entry>& entries, int sectionLine, const std::string& source,
                        ProblemFile& file) {
  ProblemKeys keys(source, sectionLine);
  static const std::set<std::string> geometryKeys = {
      "name", "robot", "world", "objective", "objective.threshold", "threshold",
      "volume.min.x", "volume.min.y", "volume.min.z", "volume.max.x", "volume.max.y", "volume.max.z"};
  for (const Entry& e : entries) {
    const std::string key = e.key.substr(std::string("problem.").size());
    if (key == "control") {
      throw InputError(locate(source, e).describe() + ": kinodynamic problems ('" + e.value +
                       "') are not supported; only rigid bodies in SE(2) and SE(3)");
    }
    const bool poseKey = key.rfind("start.", 0) == 0 || key.rfind("goal.", 0) == 0;
    if (poseKey || geometryKeys.count(key) != 0) {
      keys.add(e);
    } else {
      // sampler, longest_valid_segment_fraction, ...: space-information parameters, checked when
      // they are applied (planning_problem.cpp).
      file.spaceParameters.push_back({key, e.value, locate(source, e)});
    }
    if (poseKey) {
      const std::string rest = key.substr(key.find('.') + 1);
      static const std::set<std::string> poseFields = {"x", "y", "z", "theta", "axis.x", "axis.y", "axis.z"};
      if (poseFields.count(rest) == 0) {
        throw InputError(locate(source, e).describe() + ": unknown pose field '" + rest +
                         "' (expected x, y, theta, and for SE(3) z, axis.x, axis.y, axis.z)");
      }
    }
  }

  // SE(3) when any start or goal key beyond x, y, theta is present; then all must be.
  bool se3 = false;
  for (const char* which : {"start.", "goal."}) {
    for (const std::string& k : se3OnlyPoseKeys()) se3 = se3 || keys.has(which + k);
  }
  file.space = se3 ? RigidBodySpace::se3 : RigidBodySpace::se2;
  file.start = readPose(keys, "start", file.space, source);
  file.goal = readPose(keys, "goal", file.space, source);

  if (keys.has("name")) file.name = keys.get("name").value;
  const Entry& robot = keys.get("robot");
  const Entry& world = keys.get("world");
  if (robot.value.empty()) throw InputError(locate(source, robot).describe() + ": the robot file name is empty");
  if (world.value.empty()) throw InputError(locate(source, world).describe() + ": the world file name is empty");
  file.robotPath = resolvePath(robot.value, file.directory);
  file.worldPath = resolvePath(world.value, file.directory);
  file.robotLocation = locate(source, robot);
  file.worldLocation = locate(source, world);

  // The volume: all of its keys or none (z only for SE(3); OMPL.app ignores it for SE(2)).
  std::vector<std::string> volumeKeys = {"volume.min.x", "volume.min.y", "volume.max.x", "volume.max.y"};
  if (file.space == RigidBodySpace::se3) {
    volumeKeys.push_back("volume.min.z");
    volumeKeys.push_back("volume.max.z");
  }
  const bool anyVolume = std::any_of(volumeKeys.begin(), volumeKeys.end(), [&](const std::string& k) { return keys.has(k); });
  if (anyVolume) {
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
    lo.x() = keys.number("volume.min.x");
    lo.y() = keys.number("volume.min.y");
    hi.x() = keys.number("volume.max.x");
    hi.y() = keys.number("volume.max.y");
    if (file.space == RigidBodySpace::se3) {
      lo.z() = keys.number("volume.min.z");
      hi.z() = keys.number("volume.max.z");
    }
    const int dims = file.space == RigidBodySpace::se3 ? 3 : 2;
    const char* axes[] = {"x", "y", "z"};
    for (int i = 0; i < dims; ++i) {
      if (!(lo[i] < hi[i])) {
        throw InputError(locate(source, keys.get(std::string("volume.max.") + axes[i])).describe() +
                         ": must be greater than volume.min." + axes[i]);
      }
    }
    file.volume = Eigen::AlignedBox3d(lo, hi);
  }

  if (keys.has("objective")) {
    file.objective = parseObjective(keys.get("objective").value, locate(source, keys.get("objective")));
  }
  if (keys.has("objective.threshold")) file.objectiveThreshold = keys.number("objective.threshold");
  if (keys.has("threshold")) {
    const Entry& e = keys.get("threshold");
    file.goalThreshold = parseNumber(e, source);
    if (file.goalThreshold < 0.0) throw InputError(locate(source, e).describe() + ": must be >= 0");
  }
}

void readBenchmarkSection(const std::vector<Entry>& entries, const std::string& source, ProblemFile& file) {
  std::map<std::string, int> seen;
  for (const Entry& e : entries) {
    const std::string key = e.key.substr(std::string("benchmark.").size());
    const auto [it, inserted] = seen.emplace(key, e.line);
    if (!inserted) {
      throw InputError(locate(source, e).describe() + ": repeated (first at line " + std::to_string(it->second) + ")");
    }
    BenchmarkSection& b = file.benchmark;
    if (key == "time_limit") {
      b.timeLimit = parsePositive(e, source);
    } else if (key == "mem_limit") {
      b.memoryLimit = parsePositive(e, source);
    } else if (key == "run_count") {
      b.runCount = parsePositiveInt(e, source);
    } else if (key == "output") {
      b.output = resolvePath(e.value, file.directory);
    } else if (key == "simplify") {
      b.simplify = parseFlag(e, source);
    } else if (key == "save_paths") {
      if (e.value != "all" && e.value != "shortest" && e.value != "none") {
        throw InputError(locate(source, e).describe() + ": expected all, shortest or none, got '" + e.value + "'");
      }
      b.savePaths = e.value;
    } else {
      file.warnings.push_back(locate(source, e).describe() + ": unknown benchmark key, ignored");
    }
  }
}

void readPlannerSection(const std::vector<Entry>& entries, const std::string& source, ProblemFile& file) {
  const std::vector<std::string>& known = knownPlannerNames();
  std::set<std::string> ignored;  // unknown planners: their parameter lines are ignored too
  for (const Entry& e : entries) {
    const std::string key = e.key.substr(std::string("planner.").size());
    const auto dot = key.find('.');
    const std::string name = key.substr(0, dot);
    if (dot == std::string::npos) {
      if (std::find(known.begin(), known.end(), name) == known.end()) {
        file.warnings.push_back(locate(source, e).describe() + ": unknown planner '" + name + "', ignored");
        ignored.insert(name);
        continue;
      }
      PlannerEntry planner;
      planner.name = name;
      planner.label = name;
      planner.location = locate(source, e);
      file.planners.push_back(planner);
      continue;
    }
    if (ignored.count(name) != 0) continue;
    // A parameter belongs to the latest instance of its planner.
    auto latest = std::find_if(file.planners.rbegin(), file.planners.rend(),
                               [&](const PlannerEntry& p) { return p.name == name; });
    if (latest == file.planners.rend()) {
      file.warnings.push_back(locate(source, e).describe() + ": no '" + name + "=' line before this parameter, ignored");
      continue;
    }
    const std::string parameter = key.substr(dot + 1);
    if (parameter == "name") {
      latest->label = e.value;
    } else {
      latest->parameters.push_back({parameter, e.value, locate(source, e)});
    }
  }
}

}  // namespace

std::string SourceLocation::describe() const {
  std::string s = file;
  if (line > 0) s += ":" + std::to_string(line);
  s += ": key '" + key + "'";
  return s;
}

Pose ProblemPose::toPose() const {
  Pose pose = Pose::Identity();
  pose.translate(position);
  const double n = axis.norm();
  // A zero axis is only accepted with a zero angle (readPose): the identity rotation.
  if (n > 0.0) pose.rotate(Eigen::AngleAxisd(theta, axis / n));
  return pose;
}

ObjectiveKind parseObjective(const std::string& value, const SourceLocation& where) {
  static const std::vector<std::pair<std::string, ObjectiveKind>> names = {
      {"length", ObjectiveKind::length}, {"max_min_clearance", ObjectiveKind::maxMinClearance}};
  if (!value.empty()) {
    for (const auto& [name, kind] : names) {
      if (name.compare(0, value.size(), value) == 0) return kind;
    }
  }
  throw InputError(where.describe() + ": unknown objective '" + value + "' (expected length or max_min_clearance)");
}

ProblemFile parseProblemFile(std::istream& in, const std::string& sourceName, const std::string& directory) {
  std::ostringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (in.bad()) throw InputError(sourceName + ": cannot read the file");
  if (text.find('\0') != std::string::npos) throw InputError(sourceName + ": not a text file (contains a NUL byte)");

  std::vector<Entry> located;
  std::vector<SectionHeader> sections;
  scanLines(text, sourceName, located, sections);
  const std::vector<Entry> entries = parseWithBoost(text, sourceName, located);

  ProblemFile file;
  file.path = sourceName;
  file.directory = directory;
  file.name = fs::path(sourceName).stem().string();

  // A repeated [problem] or [benchmark] would make its keys ambiguous; [planner] may repeat (its
  // lines only add instances).
  int problemLine = 0;
  std::map<std::string, int> headerLines;
  for (const SectionHeader& s : sections) {
    if (s.name == "problem" || s.name == "benchmark") {
      const auto [it, inserted] = headerLines.emplace(s.name, s.line);
      if (!inserted) {
        throw InputError(sourceName + ":" + std::to_string(s.line) + ": section [" + s.name +
                         "] appears again (first at line " + std::to_string(it->second) + ")");
      }
    }
    if (s.name == "problem" && problemLine == 0) problemLine = s.line;
  }
  if (problemLine == 0) throw InputError(sourceName + ": no [problem] section");

  std::vector<Entry> problem, benchmark, planner;
  for (const Entry& e : entries) {
    if (e.key.rfind("problem.", 0) == 0) {
      problem.push_back(e);
    } else if (e.key.rfind("benchmark.", 0) == 0) {
      benchmark.push_back(e);
    } else if (e.key.rfind("planner.", 0) == 0) {
      planner.push_back(e);
    } else {
      file.warnings.push_back(locate(sourceName, e).describe() + ": unknown key, ignored");
    }
  }
  readProblemSection(problem, problemLine, sourceName, file);
  readBenchmarkSection(benchmark, sourceName, file);
  readPlannerSection(planner, sourceName, file);
  return file;
}

ProblemFile readProblemFile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": problem file does not exist");
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, not a problem file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the problem file");
  return parseProblemFile(in, path, fs::path(path).parent_path().string());
}

}  // namespace adsd::planner
