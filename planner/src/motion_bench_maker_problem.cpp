#include "adsd/planner/motion_bench_maker_problem.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "adsd/error.h"
#include "input_file.h"
#include "yaml_input.h"

namespace adsd::planner {

namespace {

namespace fs = std::filesystem;

std::string trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  const auto end = s.find_last_not_of(" \t\r\n");
  return s.substr(begin, end - begin + 1);
}

std::string resolvePath(const std::string& value, const std::string& directory) {
  const fs::path p(value);
  if (p.is_absolute() || directory.empty()) return p.lexically_normal().string();
  return (fs::path(directory) / p).lexically_normal().string();
}

/// The same line rules as the OMPL.app reader (problem_file.cpp): `#` starts a comment anywhere,
/// blank lines are skipped, `[name]` sets the section, `key = value` with blanks trimmed, CR LF
/// and lone CR line ends accepted, any other control character refused.
struct Line {
  std::string section, key, value;
  int line = 0;
};

std::vector<Line> scanLines(const std::string& text, const std::string& source, std::vector<std::string>& warnings,
                            int& problemLine) {
  std::vector<Line> lines;
  std::string normalized = text;
  takeLoneCarriageReturnsAsLineEnds(normalized);
  std::istringstream in(normalized);
  std::string raw, section;
  int number = 0;
  while (std::getline(in, raw)) {
    ++number;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    const std::string s = trim(raw.substr(0, raw.find('#')));
    if (s.empty()) continue;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const auto c = static_cast<unsigned char>(s[i]);
      if ((c < 0x20 && c != '\t') || c == 0x7f) {
        char code[8];
        std::snprintf(code, sizeof code, "0x%02x", static_cast<unsigned>(c));
        throw InputError(source + ":" + std::to_string(number) + ": control character " + code +
                         " (keys and values are text on one line)");
      }
    }
    const std::string at = source + ":" + std::to_string(number) + ": ";
    if (s.front() == '[') {
      if (s.back() != ']' || s.size() < 3) throw InputError(at + "malformed section header");
      section = trim(s.substr(1, s.size() - 2));
      if (section == "problem" && problemLine == 0) problemLine = number;
      if (section != "problem") warnings.push_back(at + "unknown section [" + section + "], its keys ignored");
      continue;
    }
    const auto eq = s.find('=');
    if (eq == std::string::npos || trim(s.substr(0, eq)).empty()) {
      throw InputError(at + "expected 'key = value', a [section] or a comment");
    }
    lines.push_back({section, trim(s.substr(0, eq)), trim(s.substr(eq + 1)), number});
  }
  return lines;
}

}  // namespace

std::string defaultRobotsDirectory() {
  if (const char* dir = std::getenv("ADSD_ROBOTS"); dir != nullptr && *dir != '\0') return dir;
  const char* home = std::getenv("HOME");
  return std::string(home != nullptr ? home : "") + "/.cache/adsd/robots";
}

std::string expandPathVariables(const std::string& value, const SourceLocation& where) {
  std::string out;
  std::size_t i = 0;
  while (i < value.size()) {
    const std::size_t open = value.find("${", i);
    if (open == std::string::npos) {
      out += value.substr(i);
      break;
    }
    out += value.substr(i, open - i);
    const std::size_t close = value.find('}', open + 2);
    if (close == std::string::npos) throw InputError(where.describe() + ": '${' without a closing '}'");
    const std::string name = value.substr(open + 2, close - open - 2);
    if (name == "ADSD_ROBOTS") {
      out += defaultRobotsDirectory();
    } else {
      const char* v = std::getenv(name.c_str());
      if (name.empty() || v == nullptr) {
        throw InputError(where.describe() + ": the environment variable '" + name +
                         "' is not set (only ${ADSD_ROBOTS} has a default)");
      }
      out += v;
    }
    i = close + 1;
  }
  return out;
}

MotionBenchMakerProblem parseMotionBenchMakerProblem(const std::string& text, const std::string& sourceName,
                                                     const std::string& directory) {
  requireNarrowText(text, sourceName);
  MotionBenchMakerProblem problem;
  problem.path = sourceName;
  problem.directory = directory;
  problem.name = fs::path(sourceName).stem().string();
  int sectionLine = 0;  // the [problem] header's
  const std::vector<Line> lines = scanLines(text, sourceName, problem.warnings, sectionLine);

  std::map<std::string, Line> keys;
  for (const Line& l : lines) {
    const SourceLocation where{sourceName, l.line, l.section.empty() ? l.key : l.section + "." + l.key};
    if (l.section.empty()) throw InputError(where.describe() + ": outside the [problem] section");
    if (l.section != "problem") continue;
    static const std::set<std::string> known = {"name", "robot", "srdf", "scene", "request", "package_path"};
    if (known.count(l.key) == 0) {
      problem.warnings.push_back(where.describe() + ": unknown key, ignored");
      continue;
    }
    if (const auto [it, inserted] = keys.emplace(l.key, l); !inserted) {
      throw InputError(where.describe() + ": repeated (first at line " + std::to_string(it->second.line) + ")");
    }
    if (l.value.empty()) throw InputError(where.describe() + ": the value is empty");
  }
  const auto location = [&](const Line& l) { return SourceLocation{sourceName, l.line, "problem." + l.key}; };
  const auto path = [&](const std::string& key, SourceLocation& where) -> std::string {
    const auto it = keys.find(key);
    if (it == keys.end()) {
      throw InputError(sourceName + (sectionLine > 0 ? ":" + std::to_string(sectionLine) : "") + ": key 'problem." +
                       key + "' is missing from the [problem] section");
    }
    where = location(it->second);
    return resolvePath(expandPathVariables(it->second.value, where), directory);
  };
  if (keys.count("name") != 0) problem.name = keys.at("name").value;
  problem.robotPath = path("robot", problem.robotLocation);
  problem.scenePath = path("scene", problem.sceneLocation);
  problem.requestPath = path("request", problem.requestLocation);
  if (keys.count("srdf") != 0) problem.srdfPath = path("srdf", problem.srdfLocation);
  if (const auto it = keys.find("package_path"); it != keys.end()) {
    const SourceLocation where = location(it->second);
    const std::string expanded = expandPathVariables(it->second.value, where);
    std::size_t from = 0;
    while (from <= expanded.size()) {
      const std::size_t colon = std::min(expanded.find(':', from), expanded.size());
      const std::string dir = trim(expanded.substr(from, colon - from));
      if (!dir.empty()) problem.packagePath.push_back(resolvePath(dir, directory));
      from = colon + 1;
    }
  }
  return problem;
}

MotionBenchMakerProblem readMotionBenchMakerProblem(const std::string& path) {
  const std::string text = readInputFile(path, "problem file");
  return parseMotionBenchMakerProblem(text, path, fs::path(path).parent_path().string());
}

}  // namespace adsd::planner
