#include "adsd/planner/problem_file.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include <locale.h>  // newlocale, strtod_l (POSIX): numbers read in the C locale
#include <stdlib.h>

#include <boost/program_options/options_description.hpp>
#include <boost/program_options/parsers.hpp>

#include "adsd/error.h"
#include "adsd/tolerances.h"
#include "decimal_number.h"
#include "input_file.h"
#include "adsd/planner/planner_registry.h"
#include "adsd/planner/shipped_problems.h"

namespace adsd::planner {

using detail::isDecimalNumber;

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

/// The largest |coordinate| of a start, a goal or a volume bound (length units): the distance
/// query's limit for a pose's translation (tolerance::kMaxCoordinate, 1e75), so that no state the
/// planner draws within the volume is a pose the query refuses (with 1e150 allowed, `adsd plan`
/// printed its solution and then stopped on the query's refusal). OMPL's maximum extent, the root
/// of the sum of the squared axis extents, stays finite far beyond it.
constexpr double kMaxCoordinateMagnitude = tolerance::kMaxCoordinate;

/// OMPL's StateSpace::setLongestValidSegmentFraction throws unless the fraction f satisfies
/// eps <= f <= 1 - eps with eps the machine epsilon of double (dimensionless).
constexpr double kOmplSegmentFractionMargin = std::numeric_limits<double>::epsilon();
/// CForest's threads and AnytimePathShortening's planners each run a planner of their own, all
/// built before the time limit is watched: 100 000 ran for minutes past a 0.2 s limit and took
/// gigabytes, 2^31 ended in bad_alloc (an adversarial review).
constexpr std::uint64_t kMaxPlannerThreads = 256;
/// STRIDE's GNAT tree reserves room for its degree and leaf size in every node: a leaf size of
/// 2^31 ended in an internal error (vector::reserve), a degree of 2^31 ran 10 s past its limit.
/// OMPL's defaults are 16 and 6.
constexpr std::uint64_t kMaxTreeDegree = 1000;
/// OMPL's default longest_valid_segment_fraction.
constexpr double kOmplDefaultSegmentFraction = 0.01;
/// The most states a discrete check of a motion across the whole space may take: 1e5, about a
/// tenth of a second of checks (OMPL's defaults take 100).
constexpr double kMaxStatesPerMotion = 1e5;

/// At most this many characters of a value are echoed in a message (a line may be 8 KB).
constexpr std::size_t kMaxEchoedCharacters = 60;

std::string trim(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r\n");
  if (begin == std::string::npos) return "";
  const auto end = s.find_last_not_of(" \t\r\n");
  return s.substr(begin, end - begin + 1);
}

/// Text from the file in quotes, shortened to kMaxEchoedCharacters. Lines holding control
/// characters are rejected by scanLines before anything is echoed, so this only shortens.
std::string quoted(const std::string& text) {
  if (text.size() <= kMaxEchoedCharacters) return "'" + text + "'";
  return "'" + text.substr(0, kMaxEchoedCharacters) + "...'";
}

/// A control character (other than the tab, which is whitespace) would break the one-line rule of
/// every message that echoes a key or a value, and no key or value of a problem file holds one.
/// Returns its position in \p s, or npos.
std::size_t findControlCharacter(const std::string& s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if ((c < 0x20 && c != '\t') || c == 0x7f) return i;
  }
  return std::string::npos;
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
    // Windows line ends (CR LF) are accepted: the CR goes with the line end.
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    const std::string s = trim(raw.substr(0, raw.find('#')));
    if (s.empty()) continue;
    if (const std::size_t at = findControlCharacter(s); at != std::string::npos) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02x", static_cast<unsigned>(static_cast<unsigned char>(s[at])));
      throw InputError(source + ":" + std::to_string(line) + ": control character " + code + " at column " +
                       std::to_string(raw.find(s) + at + 1) + " (keys and values are text on one line)");
    }
    if (s.front() == '[') {
      if (s.back() != ']' || s.size() < 3) {
        throw InputError(source + ":" + std::to_string(line) + ": malformed section header " + quoted(s));
      }
      const std::string name = trim(s.substr(1, s.size() - 2));
      // Boost (and so OMPL.app) keeps spaces inside the brackets: "[ problem ]" is a section named
      // " problem ", whose keys were then reported missing from [problem].
      if (name != s.substr(1, s.size() - 2)) {
        throw InputError(source + ":" + std::to_string(line) + ": section header " + quoted(s) +
                         " has spaces inside its brackets, which make another section (write '[" + name + "]')");
      }
      sections.push_back({name, line});
      prefix = name + ".";
      continue;
    }
    const auto eq = s.find('=');
    if (eq == std::string::npos || trim(s.substr(0, eq)).empty()) {
      throw InputError(source + ":" + std::to_string(line) + ": expected 'key = value', a [section] or a comment, got " +
                       quoted(s));
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
  // strtod reads with the decimal point of the process's locale: an OMPL program that called
  // setlocale(LC_ALL, "") under a decimal-comma locale would have every "0.5" refused. The C
  // locale's reading, whatever the process's, is the file format's (and OMPL's own conversion's).
  static const locale_t classic = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  char* end = nullptr;
  const double x = strtod_l(v.c_str(), &end, classic);
  const bool readWhole = end == v.c_str() + v.size();
  if (readWhole && !std::isfinite(x)) {
    throw InputError(locate(source, e).describe() + ": expected a finite number, got " + quoted(v));
  }
  if (!readWhole || !isDecimalNumber(v)) {
    throw InputError(locate(source, e).describe() + ": expected a number, got " + quoted(v));
  }
  // A value below the smallest double rounds to a subnormal or zero (strtod's ERANGE), as it does
  // in OMPL's conversion: accepted, and checked by the caller's rule like any other.
  return x;
}

/// A coordinate (start, goal, volume): finite and within kMaxCoordinateMagnitude.
double parseCoordinate(const Entry& e, const std::string& source) {
  const double x = parseNumber(e, source);
  if (std::fabs(x) > kMaxCoordinateMagnitude) {
    throw InputError(locate(source, e).describe() + ": " + quoted(e.value) +
                     " is too large for a coordinate (at most 1e75 in magnitude, the distance query's limit)");
  }
  return x;
}

/// A whole number written as digits (an optional '+'), within [\p least, \p most]. OMPL reads whole
/// parameters with stoul, which would take "1e3" as 1, "2.5" as 2 and "-1" as 2^64 - 1.
std::uint64_t parseWhole(const Entry& e, const std::string& source, std::uint64_t least, std::uint64_t most) {
  const std::string& v = e.value;
  const std::string digits = !v.empty() && v.front() == '+' ? v.substr(1) : v;
  const bool allDigits = !digits.empty() && std::all_of(digits.begin(), digits.end(), [](unsigned char c) {
    return std::isdigit(c) != 0;
  });
  const std::string range = "from " + std::to_string(least) + " to " + std::to_string(most);
  if (!allDigits) {
    throw InputError(locate(source, e).describe() + ": expected a whole number " + range + ", got " + quoted(v));
  }
  const std::size_t first = std::min(digits.find_first_not_of('0'), digits.size());
  // More than 20 significant digits exceeds 64 bits; otherwise strtoull reads it exactly.
  errno = 0;
  const unsigned long long x = digits.size() - first > 20 ? 0 : std::strtoull(digits.c_str(), nullptr, 10);
  if (digits.size() - first > 20 || errno == ERANGE || x < least || x > most) {
    throw InputError(locate(source, e).describe() + ": expected a whole number " + range + ", got " + quoted(v));
  }
  return x;
}

int parsePositiveInt(const Entry& e, const std::string& source) {
  const double x = parseNumber(e, source);
  if (x != std::floor(x) || x < 1 || x > 1e9) {
    throw InputError(locate(source, e).describe() + ": expected a positive whole number, got " + quoted(e.value));
  }
  return static_cast<int>(x);
}

double parsePositive(const Entry& e, const std::string& source) {
  const double x = parseNumber(e, source);
  if (!(x > 0.0)) throw InputError(locate(source, e).describe() + ": expected a number > 0, got " + quoted(e.value));
  return x;
}

/// How a value handed to OMPL as text (si->params() or a planner's params()) must look, so that
/// OMPL's conversion and setter accept it and it means what it says.
enum class ValueRule {
  flag,               ///< 0, 1, true or false (OMPL reads "no", "off" and "0.0" as true)
  anyReal,            ///< a finite decimal number
  nonNegative,        ///< >= 0
  positive,           ///< > 0
  unitInterval,       ///< in [0, 1]
  positiveFraction,   ///< in (0, 1]
  segmentFraction,    ///< in [eps, 1 - eps] (kOmplSegmentFractionMargin)
  fractionFromEps,    ///< in [eps, 1]
  count,              ///< a whole number in [0, 2^32 - 1] (OMPL's unsigned int)
  positiveCount,      ///< a whole number in [1, 2^32 - 1]
  threadCount,        ///< a whole number in [1, kMaxPlannerThreads]
  treeDegree,         ///< a whole number in [1, kMaxTreeDegree]
  text,               ///< passed as written
};

/// The rule for `[problem]` key \p key, when the key is a parameter of OMPL's SpaceInformation
/// (OMPL 1.5 declares these two; `sampler` is ours, checked when the problem is built).
std::optional<ValueRule> spaceParameterRule(const std::string& key) {
  static const std::map<std::string, ValueRule> rules = {
      {"longest_valid_segment_fraction", ValueRule::segmentFraction},
      // Zero makes OMPL throw; it is a multiplier of the number of motion segments.
      {"valid_segment_count_factor", ValueRule::positiveCount},
  };
  const auto it = rules.find(key);
  if (it == rules.end()) return std::nullopt;
  return it->second;
}

/// The rule for planner parameter \p name: every parameter the planners of planner_registry.cpp
/// declare in OMPL 1.5 (listed from their params()); a name shared by several planners means the
/// same there. A name none of them declares is never set (the planner warns and ignores it).
std::optional<ValueRule> plannerParameterRule(const std::string& name) {
  using R = ValueRule;
  static const std::map<std::string, ValueRule> rules = {
      // Switches.
      {"balanced", R::flag}, {"cache_cc", R::flag}, {"delay_collision_checking", R::flag},
      {"delay_rewiring_to_first_solution", R::flag}, {"drop_unconnected_samples_on_prune", R::flag},
      {"extended_fmt", R::flag}, {"find_approximate_solutions", R::flag}, {"focus_search", R::flag},
      {"heuristics", R::flag}, {"hybridize", R::flag}, {"informed_sampling", R::flag},
      {"intermediate_states", R::flag}, {"nearest_k", R::flag}, {"new_state_rejection", R::flag},
      {"optimality", R::flag}, {"ordered_sampling", R::flag}, {"pruned_measure", R::flag},
      {"sample_rejection", R::flag}, {"shortcut", R::flag}, {"stop_on_each_solution_improvement", R::flag},
      {"tree_pruning", R::flag}, {"update_children", R::flag}, {"use_admissible_heuristic", R::flag},
      {"use_graph_pruning", R::flag}, {"use_just_in_time_sampling", R::flag}, {"use_k_nearest", R::flag},
      {"use_projected_distance", R::flag}, {"use_strict_queue_ordering", R::flag},
      // Probabilities and fractions.
      {"goal_bias", R::unitInterval},
      {"prune_threshold", R::unitInterval}, {"prune_threshold_as_fractional_cost_change", R::unitInterval},
      {"frontier_node_ratio", R::unitInterval},
      // KPIECE throws outside (0, 1] when set, and its set-up below machine epsilon (1e-300 passed
      // the setter and ended adsd plan with an internal error; an adversarial review).
      {"border_fraction", R::positiveFraction}, {"failed_expansion_score_factor", R::fractionFromEps},
      {"min_valid_path_fraction", R::fractionFromEps},
      // The SPARS deltas are fractions of the space's extent.
      {"dense_delta_fraction", R::positiveFraction}, {"sparse_delta_fraction", R::positiveFraction},
      // Lengths and radii (0 for range: OMPL picks one from the space's extent).
      {"range", R::nonNegative}, {"pruning_radius", R::nonNegative}, {"selection_radius", R::nonNegative},
      {"frontier_threshold", R::nonNegative}, {"rejection_variant_alpha", R::nonNegative},
      // Factors and temperatures that divide or multiply.
      {"epsilon", R::positive}, {"init_temperature", R::positive}, {"temp_change_factor", R::positive},
      {"radius_multiplier", R::positive}, {"rewire_factor", R::positive}, {"stretch_factor", R::positive},
      {"cost_threshold", R::anyReal},
      // Counts (OMPL's unsigned int: a negative number would wrap to about 4e9).
      {"max_nearest_neighbors", R::count}, {"max_failures", R::count}, {"rejection_variant", R::count},
      {"degree", R::treeDegree}, {"max_degree", R::treeDegree}, {"min_degree", R::treeDegree},
      {"max_pts_per_leaf", R::treeDegree}, {"estimated_dimension", R::positiveCount},
      {"max_hybrid_paths", R::positiveCount}, {"num_planners", R::threadCount}, {"num_samples", R::positiveCount},
      {"num_threads", R::threadCount}, {"number_sampling_attempts", R::positiveCount},
      {"ordering_batch_size", R::positiveCount}, {"samples_per_batch", R::positiveCount},
      // AnytimePathShortening's list of planners.
      {"planners", R::text},
  };
  const auto it = rules.find(name);
  if (it == rules.end()) return std::nullopt;
  return it->second;
}

/// Checks \p e's value against \p rule; throws InputError naming file, line and key otherwise.
void checkValue(const Entry& e, ValueRule rule, const std::string& source) {
  const auto fail = [&](const std::string& expected) {
    throw InputError(locate(source, e).describe() + ": expected " + expected + ", got " + quoted(e.value));
  };
  constexpr std::uint64_t kUnsignedIntMax = std::numeric_limits<std::uint32_t>::max();
  switch (rule) {
    case ValueRule::text:
      return;
    case ValueRule::flag: {
      std::string v = e.value;
      std::transform(v.begin(), v.end(), v.begin(), [](unsigned char c) { return std::tolower(c); });
      if (v != "0" && v != "1" && v != "true" && v != "false") fail("0, 1, true or false");
      return;
    }
    case ValueRule::count:
      parseWhole(e, source, 0, kUnsignedIntMax);
      return;
    case ValueRule::positiveCount:
      parseWhole(e, source, 1, kUnsignedIntMax);
      return;
    case ValueRule::threadCount:
      parseWhole(e, source, 1, kMaxPlannerThreads);
      return;
    case ValueRule::treeDegree:
      parseWhole(e, source, 1, kMaxTreeDegree);
      return;
    default:
      break;
  }
  const double x = parseNumber(e, source);
  switch (rule) {
    case ValueRule::nonNegative:
      if (!(x >= 0.0)) fail("a number >= 0");
      break;
    case ValueRule::positive:
      if (!(x > 0.0)) fail("a number > 0");
      break;
    case ValueRule::unitInterval:
      if (!(x >= 0.0 && x <= 1.0)) fail("a number from 0 to 1");
      break;
    case ValueRule::positiveFraction:
      if (!(x > 0.0 && x <= 1.0)) fail("a number > 0 and <= 1");
      break;
    case ValueRule::segmentFraction:
      if (!(x >= kOmplSegmentFractionMargin && x <= 1.0 - kOmplSegmentFractionMargin)) {
        fail("a number > 0 and < 1 (OMPL's bounds: 2.2e-16 to 1 - 2.2e-16)");
      }
      break;
    case ValueRule::fractionFromEps:
      if (!(x >= kOmplSegmentFractionMargin && x <= 1.0)) fail("a number > 0 and <= 1 (OMPL's bounds: 2.2e-16 to 1)");
      break;
    default:
      break;
  }
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
  double coordinate(const std::string& key) const { return parseCoordinate(get(key), source_); }

 private:
  std::string source_;
  int sectionLine_;
  std::map<std::string, Entry> keys_;
};

ProblemPose readPose(const ProblemKeys& keys, const std::string& which, RigidBodySpace space,
                     const std::string& source) {
  ProblemPose pose;
  pose.location = locate(source, keys.get(which + ".x"));
  pose.positionLocations[0] = pose.location;
  pose.position.x() = keys.coordinate(which + ".x");
  pose.positionLocations[1] = locate(source, keys.get(which + ".y"));
  pose.position.y() = keys.coordinate(which + ".y");
  pose.theta = keys.number(which + ".theta");
  if (space == RigidBodySpace::se3) {
    pose.positionLocations[2] = locate(source, keys.get(which + ".z"));
    pose.position.z() = keys.coordinate(which + ".z");
    pose.axis = Vec3(keys.number(which + ".axis.x"), keys.number(which + ".axis.y"), keys.number(which + ".axis.z"));
    if (pose.axis.cwiseAbs().maxCoeff() == 0.0 && pose.theta != 0.0) {
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
  std::map<std::string, int> spaceParameterLines;  // each space parameter at most once
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
      // sampler, longest_valid_segment_fraction, ...: space-information parameters. OMPL's own
      // ones are checked here, so that OMPL neither throws on them nor takes a value that breaks
      // its motion checking; `sampler` and unknown keys when the problem is built
      // (planning_problem.cpp).
      const auto [it, inserted] = spaceParameterLines.emplace(key, e.line);
      if (!inserted) {
        throw InputError(locate(source, e).describe() + ": repeated (first at line " + std::to_string(it->second) +
                         ")");
      }
      if (const std::optional<ValueRule> rule = spaceParameterRule(key)) checkValue(e, *rule, source);
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

  // OMPL checks a motion in valid_segment_count_factor states per longest valid segment, and the
  // longest motion spans 1 / longest_valid_segment_fraction segments. No single check stops at
  // the planner's time limit, so a tiny fraction (1e-8) or a huge factor made one motion check
  // run for minutes whatever --time said.
  double fraction = kOmplDefaultSegmentFraction, factor = 1.0;
  const Entry* fractionEntry = nullptr;
  const Entry* factorEntry = nullptr;
  for (const Entry& e : entries) {
    if (e.key == "problem.longest_valid_segment_fraction") fraction = parseNumber(*(fractionEntry = &e), source);
    if (e.key == "problem.valid_segment_count_factor") factor = parseNumber(*(factorEntry = &e), source);
  }
  if (factor / fraction > kMaxStatesPerMotion) {
    const auto formatNumber = [](double x) {
      std::ostringstream out;
      out << x;
      return out.str();
    };
    const Entry& culprit = fractionEntry != nullptr ? *fractionEntry : *factorEntry;
    throw InputError(locate(source, culprit).describe() + ": valid_segment_count_factor / " +
                     "longest_valid_segment_fraction is " + formatNumber(factor / fraction) + ": a motion across the " +
                     "space would be checked in that many states (at most " + formatNumber(kMaxStatesPerMotion) + ")");
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
    lo.x() = keys.coordinate("volume.min.x");
    lo.y() = keys.coordinate("volume.min.y");
    hi.x() = keys.coordinate("volume.max.x");
    hi.y() = keys.coordinate("volume.max.y");
    if (file.space == RigidBodySpace::se3) {
      lo.z() = keys.coordinate("volume.min.z");
      hi.z() = keys.coordinate("volume.max.z");
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
      if (*b.timeLimit > kMaxTimeLimitSeconds) {
        throw InputError(locate(source, e).describe() + ": " + quoted(e.value) +
                         " seconds is longer than the clock can count (at most 1e8)");
      }
    } else if (key == "mem_limit") {
      b.memoryLimit = parsePositive(e, source);
    } else if (key == "run_count") {
      b.runCount = parsePositiveInt(e, source);
    } else if (key == "output") {
      b.output = resolvePath(e.value, file.directory);
      b.outputLocation = locate(source, e);
    } else if (key == "simplify") {
      b.simplify = parseFlag(e, source);
    } else if (key == "save_paths") {
      if (e.value != "all" && e.value != "shortest" && e.value != "none") {
        throw InputError(locate(source, e).describe() + ": expected all, shortest or none, got '" + e.value + "'");
      }
      b.savePaths = e.value;
      b.savePathsLocation = locate(source, e);
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
      // OMPL.app's planner lines are `rrtconnect =`: a value there is no parameter of anything
      // (parameters are `rrtconnect.range = 2`), and silently dropping it hid the mistake.
      if (!e.value.empty()) {
        file.warnings.push_back(locate(source, e).describe() + ": a planner line takes no value ('" + name +
                                " =', parameters as '" + name + ".range = ...'); '" + e.value + "' ignored");
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
      // An empty name made a row with no planner in the summary (an outside review).
      if (e.value.empty()) throw InputError(locate(source, e).describe() + ": a planner's name may not be empty");
      latest->label = e.value;
    } else {
      if (const std::optional<ValueRule> rule = plannerParameterRule(parameter)) checkValue(e, *rule, source);
      latest->parameters.push_back({parameter, e.value, locate(source, e)});
    }
  }
}

}  // namespace

bool isPlannerSwitch(const std::string& name) { return plannerParameterRule(name) == ValueRule::flag; }

std::string SourceLocation::describe() const {
  std::string s = file;
  if (line > 0) s += ":" + std::to_string(line);
  s += ": key '" + key + "'";
  return s;
}

Pose ProblemPose::toPose() const {
  Pose pose = Pose::Identity();
  pose.translate(position);
  // Scaled by its largest component before normalizing: the norm of an axis with components near
  // 1e200 would overflow (and one near 1e-200 underflow) if taken directly.
  const double largest = axis.cwiseAbs().maxCoeff();
  // A zero axis is only accepted with a zero angle (readPose): the identity rotation.
  if (largest > 0.0) pose.rotate(Eigen::AngleAxisd(theta, (axis / largest).normalized()));
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
  std::string text = buffer.str();
  if (in.bad()) throw InputError(sourceName + ": cannot read the file");
  dropByteOrderMark(text);
  requireNarrowText(text, sourceName);
  // For this pass and Boost's alike; elsewhere a CR is a control character.
  takeLoneCarriageReturnsAsLineEnds(text);

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

namespace {

/// For a bare file name that is not here but is one of the shipped problems: where that one is.
/// The README's `adsd plan office.cfg`, run outside the problems' directory, said only that the
/// file does not exist (an outside review).
std::string shippedProblemHint(const std::string& path) {
  if (fs::path(path).has_parent_path()) return "";
  try {
    const fs::path shipped = fs::path(shippedProblemsDirectory()) / path;
    std::error_code ec;
    if (fs::is_regular_file(shipped, ec)) return " here; the shipped problem of that name is " + shipped.string();
  } catch (const InputError&) {
    // No data directory (a program linking the library): nothing to point to.
  }
  return "";
}

}  // namespace

ProblemFile readProblemFile(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path + ": problem file does not exist" + shippedProblemHint(path));
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a directory, not a problem file");
  // Read line by line: /dev/zero is one line without end, which filled the memory.
  if (!fs::is_regular_file(path, ec)) throw InputError(path + ": is a device, a pipe or a socket, not a problem file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the problem file");
  return parseProblemFile(in, path, fs::path(path).parent_path().string());
}

}  // namespace adsd::planner
