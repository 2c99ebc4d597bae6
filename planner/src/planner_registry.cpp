#include "adsd/planner/planner_registry.h"

#include <ompl/base/objectives/MaximizeMinClearanceObjective.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>

#include <algorithm>
#include <cctype>
#include <functional>
#include <map>

#include <ompl/geometric/planners/AnytimePathShortening.h>
#include <ompl/geometric/planners/cforest/CForest.h>
#include <ompl/geometric/planners/est/BiEST.h>
#include <ompl/geometric/planners/est/EST.h>
#include <ompl/geometric/planners/fmt/BFMT.h>
#include <ompl/geometric/planners/fmt/FMT.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/kpiece/BKPIECE1.h>
#include <ompl/geometric/planners/kpiece/KPIECE1.h>
#include <ompl/geometric/planners/kpiece/LBKPIECE1.h>
#include <ompl/geometric/planners/pdst/PDST.h>
#include <ompl/geometric/planners/prm/LazyPRM.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRM.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/prm/SPARS.h>
#include <ompl/geometric/planners/prm/SPARStwo.h>
#include <ompl/geometric/planners/rrt/BiTRRT.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/LBTRRT.h>
#include <ompl/geometric/planners/rrt/LazyRRT.h>
#include <ompl/geometric/planners/rrt/RRT.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/geometric/planners/rrt/RRTsharp.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/geometric/planners/rrt/TRRT.h>
#include <ompl/geometric/planners/sbl/SBL.h>
#include <ompl/geometric/planners/sst/SST.h>
#include <ompl/geometric/planners/stride/STRIDE.h>
#include <ompl/util/Console.h>

#include "adsd/error.h"

namespace adsd::planner {

namespace {

namespace og = ompl::geometric;
using Allocator = std::function<ompl::base::PlannerPtr(const ompl::base::SpaceInformationPtr&)>;

template <class P>
Allocator allocator() {
  return [](const ompl::base::SpaceInformationPtr& si) { return std::make_shared<P>(si); };
}

/// OMPL.app's lower-case names (shared/OMPLAPP-CFG.md), in a stable order.
const std::vector<std::pair<std::string, Allocator>>& registry() {
  static const std::vector<std::pair<std::string, Allocator>> planners = {
      {"rrtconnect", allocator<og::RRTConnect>()},
      {"rrt", allocator<og::RRT>()},
      {"rrtstar", allocator<og::RRTstar>()},
      {"informedrrtstar", allocator<og::InformedRRTstar>()},
      {"rrtsharp", allocator<og::RRTsharp>()},
      {"lazyrrt", allocator<og::LazyRRT>()},
      {"trrt", allocator<og::TRRT>()},
      {"bitrrt", allocator<og::BiTRRT>()},
      {"lbtrrt", allocator<og::LBTRRT>()},
      {"prm", allocator<og::PRM>()},
      {"prmstar", allocator<og::PRMstar>()},
      {"lazyprm", allocator<og::LazyPRM>()},
      {"lazyprmstar", allocator<og::LazyPRMstar>()},
      {"spars", allocator<og::SPARS>()},
      {"spars2", allocator<og::SPARStwo>()},
      {"kpiece", allocator<og::KPIECE1>()},
      {"bkpiece", allocator<og::BKPIECE1>()},
      {"lbkpiece", allocator<og::LBKPIECE1>()},
      {"est", allocator<og::EST>()},
      {"biest", allocator<og::BiEST>()},
      {"sbl", allocator<og::SBL>()},
      {"stride", allocator<og::STRIDE>()},
      {"pdst", allocator<og::PDST>()},
      // Named as OMPL renames its k-nearest BIT* (its default), warning on every construction
      // that "BITstar" is reserved for the r-disc version.
      {"bitstar",
       [](const ompl::base::SpaceInformationPtr& si) { return std::make_shared<og::BITstar>(si, "kBITstar"); }},
      {"fmt", allocator<og::FMT>()},
      {"bfmt", allocator<og::BFMT>()},
      {"sst", allocator<og::SST>()},
      {"cforest", allocator<og::CForest>()},
      {"anytimepathshortening", allocator<og::AnytimePathShortening>()},
  };
  return planners;
}

}  // namespace

const std::vector<std::string>& knownPlannerNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& entry : registry()) n.push_back(entry.first);
    return n;
  }();
  return names;
}

ompl::base::PlannerPtr makePlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si) {
  for (const auto& [known, make] : registry()) {
    if (known == name) return make(si);
  }
  return nullptr;
}

bool isOptimizingPlanner(const std::string& name) {
  static const std::vector<std::string> optimizing = {"rrtstar", "informedrrtstar", "rrtsharp", "prmstar",
                                                      "lazyprmstar", "lbtrrt", "bitstar", "fmt", "bfmt",
                                                      "sst", "cforest", "anytimepathshortening", "spars", "spars2"};
  return std::find(optimizing.begin(), optimizing.end(), name) != optimizing.end();
}

std::optional<std::string> plannerConflict(const std::string& name, const ompl::base::OptimizationObjective* objective,
                                           const ompl::base::StateSpace& space) {
  // A clearance objective, OMPL's for rigid bodies or the arms' (ArmClearanceObjective): either is
  // one to maximize, which no other objective here is.
  const bool clearance =
      objective != nullptr && objective->isCostBetterThan(ompl::base::Cost(1.0), ompl::base::Cost(0.0));
  if (clearance && (name == "fmt" || name == "bfmt")) {
    return "planner " + name + " cannot plan for the clearance objective (OMPL's FMT* and BFMT* crash with it); " +
           "use rrtstar, informedrrtstar, bitstar or prmstar";
  }
  if (clearance && (name == "trrt" || name == "bitrrt")) {
    return "planner " + name + " cannot plan for the clearance objective (OMPL's TRRT and BiTRRT keep the " +
           "objective's cost low along the tree, and the clearance objective's cost is a clearance to keep high: " +
           "they time out); use rrtstar, informedrrtstar, bitstar or prmstar";
  }
  // No objective is OMPL's default, path length.
  const bool lengthObjective =
      objective == nullptr || dynamic_cast<const ompl::base::PathLengthOptimizationObjective*>(objective) != nullptr;
  const int type = space.getType();
  const bool informedSpace = type == ompl::base::STATE_SPACE_REAL_VECTOR || type == ompl::base::STATE_SPACE_SE2 ||
                             type == ompl::base::STATE_SPACE_SE3;
  if (lengthObjective && !informedSpace && (name == "informedrrtstar" || name == "bitstar" || name == "cforest")) {
    return "planner " + name + " cannot plan for path length in this state space (" + space.getName() +
           "): OMPL's informed sampling, which it uses, works only in real-vector, SE(2) and SE(3) spaces; use " +
           "rrtstar, rrtsharp or prmstar, or the clearance objective";
  }
  return std::nullopt;
}

namespace {

/// A switch's value as OMPL reads it: "1" or "0" for 1/true and 0/false, nullopt for other text.
std::optional<std::string> switchValue(std::string value) {
  std::transform(value.begin(), value.end(), value.begin(), [](unsigned char c) { return std::tolower(c); });
  if (value == "1" || value == "true") return "1";
  if (value == "0" || value == "false") return "0";
  return std::nullopt;
}

/// Checks AnytimePathShortening's `planners` list before OMPL reads it: entries NAME or
/// NAME[PARAMETER=VALUE ...] separated by commas, each NAME a planner OMPL's list knows (its class
/// names: RRTConnect, PRM). OMPL 1.5.2 drops a name it does not know with an error in its log
/// alone (`planners = rrt,prm` ran its default planners, without a word), sets the parameters of
/// an unknown entry on the entry before it, and with none before it (`Foo[range=1]`, or ` PRM`,
/// which it reads as a nameless entry) dereferences a null planner.
void requireShorteningPlanners(const Setting& list, const std::string& name,
                               const ompl::base::SpaceInformationPtr& si) {
  std::vector<std::string> entries;
  int depth = 0;
  std::string entry;
  for (const char c : list.value + ",") {
    depth += c == '[' ? 1 : c == ']' ? -1 : 0;
    if (c == ',' && depth == 0) {
      entries.push_back(entry);
      entry.clear();
    } else {
      entry += c;
    }
  }
  if (list.value.empty()) return;  // no list: the planner's defaults
  ompl::geometric::AnytimePathShortening probe(si);
  for (const std::string& e : entries) {
    const std::size_t open = e.find('[');
    const std::string planner = e.substr(0, open);
    const bool formed = !planner.empty() && std::all_of(planner.begin(), planner.end(), [](unsigned char c) {
      return std::isalnum(c) != 0 || c == '_';
    }) && (open == std::string::npos || (e.back() == ']' && e.find_first_of("[]", open + 1) == e.size() - 1));
    if (!formed) {
      throw InputError(list.location.describe() + ": " + name + ": expected planners as NAME or " +
                       "NAME[PARAMETER=VALUE ...] separated by commas, without spaces around them, got '" + e + "'");
    }
    // The name alone: OMPL reads it without a parameter to set on a missing planner.
    const ompl::msg::LogLevel level = ompl::msg::getLogLevel();
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    bool known = false;
    try {
      known = probe.params().setParam("planners", planner) && probe.getNumPlanners() == 1;
    } catch (const std::exception&) {
      known = false;
    }
    ompl::msg::setLogLevel(level);
    if (!known) {
      throw InputError(list.location.describe() + ": " + name + " knows no planner '" + planner +
                       "' (it takes OMPL's class names, such as RRT, RRTConnect, PRM, RRTstar)");
    }
    // RRTstar[ordered_sampling=1] crashes as configurePlanner below says, inside the list too.
    const auto on = [&](const std::string& key) {
      return e.find(key + "=1") != std::string::npos || e.find(key + "=true") != std::string::npos;
    };
    if (on("ordered_sampling") && !on("informed_sampling") && !on("sample_rejection")) {
      throw InputError(list.location.describe() + ": " + name + ": '" + e + "': ordered_sampling orders the samples " +
                       "of informed or rejection sampling, and neither is on (set informed_sampling=1 or " +
                       "sample_rejection=1)");
    }
  }
}

}  // namespace

std::vector<std::string> configurePlanner(ompl::base::Planner& planner, const std::string& name,
                                          const std::vector<Setting>& settings) {
  std::vector<const Setting*> order;
  for (const Setting& s : settings) order.push_back(&s);
  std::stable_partition(order.begin(), order.end(), [](const Setting* s) { return s->key != "ordered_sampling"; });
  if (dynamic_cast<const ompl::geometric::AnytimePathShortening*>(&planner) != nullptr) {
    for (const Setting* s : order) {
      if (s->key == "planners") requireShorteningPlanners(*s, name, planner.getSpaceInformation());
    }
  }
  std::vector<std::string> warnings;
  ompl::base::ParamSet& params = planner.params();
  for (const Setting* s : order) {
    if (!params.hasParam(s->key)) {
      warnings.push_back(s->location.describe() + ": " + name + " has no parameter '" + s->key + "', ignored");
      continue;
    }
    // OMPL's own warning on a value it rejects is silenced: ours names the file and line.
    const ompl::msg::LogLevel level = ompl::msg::getLogLevel();
    ompl::msg::setLogLevel(ompl::msg::LOG_NONE);
    bool accepted = false;
    try {
      accepted = params.setParam(s->key, s->value);
    } catch (const std::exception&) {  // a number that does not parse
      accepted = false;
    }
    ompl::msg::setLogLevel(level);
    if (!accepted) throw InputError(s->location.describe() + ": " + name + " rejected the value '" + s->value + "'");
  }
  const auto reads = [&](const std::string& key, std::string& value) { return params.getParam(key, value); };
  for (auto s = order.begin(); s != order.end(); ++s) {
    // A later line for the same key overrides this one.
    const std::string& key = (*s)->key;
    if (std::any_of(s + 1, order.end(), [&](const Setting* later) { return later->key == key; })) continue;
    std::string now;
    const std::optional<std::string> wanted = switchValue((*s)->value);
    if (isPlannerSwitch(key) && wanted && reads(key, now) && now != *wanted) {
      throw InputError((*s)->location.describe() + ": " + name + " did not keep the value '" + (*s)->value +
                       "' (it reads " + now + " once all its parameters are set)");
    }
  }
  // Read through RRT*'s getters: InformedRRT* samples the informed set without declaring the
  // switch, and ordered sampling is RRT*'s alone among the registry's planners.
  const auto* rrtStar = dynamic_cast<const ompl::geometric::RRTstar*>(&planner);
  if (rrtStar != nullptr && rrtStar->getOrderedSampling() && !rrtStar->getInformedSampling() &&
      !rrtStar->getSampleRejection()) {
    auto line = std::find_if(order.begin(), order.end(), [](const Setting* s) { return s->key == "ordered_sampling"; });
    if (line == order.end()) {
      line = std::find_if(order.begin(), order.end(), [](const Setting* s) {
        return s->key == "informed_sampling" || s->key == "sample_rejection";
      });
    }
    throw InputError((line != order.end() ? (*line)->location.describe() + ": " : std::string()) + name +
                     ": ordered_sampling orders the samples of informed or rejection sampling, and neither is on "
                     "(set informed_sampling = 1 or sample_rejection = 1)");
  }
  return warnings;
}

}  // namespace adsd::planner
