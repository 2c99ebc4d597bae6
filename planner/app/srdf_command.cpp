// `adsd srdf ROBOT.urdf --out ROBOT.srdf [--states N] [--seed S] [--no-default] [--never]
//  [--package-path DIR]...`
//
// What MoveIt's setup assistant does for a robot's self-collision matrix, for a robot new to the
// program, in its order: the link pairs its kinematic tree joins (adjacentLinkPairs), those in
// contact in the default pose (disablePairsInContactAt: links that overlap where the robot is
// drawn, Atlas's two thighs), and those in contact in every one of N random states
// (disablePairsBySampling: they touch by design, a hip inside its pelvis) are written as an SRDF's
// <disable_collisions>, which an arm problem file names with `srdf = ...`
// (docs/problem-files.md). Pairs never seen in contact are disabled only with --never, since that
// is a guess the checker would then rely on. Exit status: 0 written, 2 bad input or usage.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include <tinyxml.h>

#include "adsd/cli/command_line.h"
#include "adsd/error.h"
#include "adsd/planner/arm_collision_pairs.h"
#include "adsd/planner/arm_model.h"
#include "adsd/planner/arm_pair_sampling.h"
#include "commands.h"

namespace adsd::app {

namespace {

using namespace adsd::planner;

constexpr const char* kSynopsis =
    "adsd srdf ROBOT.urdf --out ROBOT.srdf [--states N] [--seed S] [--no-default] [--never]\n"
    "                 [--package-path DIR]...";
constexpr const char* kDescription =
    "Writes the self-collision pairs to leave unchecked for a robot, as an SRDF file of\n"
    "<disable_collisions> entries (MoveIt's format, which an arm problem names with `srdf = FILE`):\n"
    "the pairs its kinematic tree joins (reason Adjacent: a parent and its child, links joined by\n"
    "fixed joints), the pairs in contact in the default pose (reason Default: every joint at 0, or\n"
    "at the midpoint of its limits when they exclude 0), and the pairs in contact in every one of\n"
    "N random joint states (reason Always: they touch by design, at any joint values), as MoveIt's\n"
    "setup assistant does. With --never, also the pairs in contact in none of them (reason\n"
    "Never). Default and Never are guesses: such a pair may still collide in other states, which\n"
    "the checker would then miss.";
constexpr const char* kDetails =
    "States are drawn uniformly within the joint limits (continuous joints in [-pi, pi]); contact is\n"
    "our distance query at threshold 0 on the links' collision meshes. Prints each Default and\n"
    "Always pair and the counts. The file is written only when everything succeeded.\n"
    "Exit status: 0 written, 2 bad input or usage (one line naming the file, the link or the option).\n";

/// MoveIt's setup assistant draws 10 000 states by default; so do we.
constexpr std::uint64_t kDefaultStates = 10000;
/// More states than this would take hours on a robot of a few dozen links.
constexpr std::uint64_t kMaxStates = 10000000;

struct SrdfArguments {
  std::string urdf;
  std::string out;
  std::vector<std::string> packagePath;
  std::uint64_t states = kDefaultStates;
  std::uint64_t seed = 1;
  bool never = false;
  bool defaultPose = true;
};

/// An existing --out file is replaced only when it is an SRDF already (its text holds a <robot>
/// element): the name of a mesh the robot reads, given by mistake, was overwritten with XML.
void requireReplaceable(const std::string& out) {
  std::error_code ec;
  if (!std::filesystem::exists(out, ec)) return;
  std::ifstream in(out, std::ios::binary);
  std::string head(65536, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.find("<robot") == std::string::npos) {
    throw cli::UsageError("--out: '" + out + "' exists and is not an SRDF (no <robot> element near its start): not " +
                          "replaced");
  }
  // A URDF has a <robot> element too (an outside review overwrote one so). Both name links and
  // joints in <link> and <joint> elements (an SRDF's groups do), but only a URDF has a joint's
  // <parent> and <child> or a link's <visual>, <collision> and <inertial>.
  for (const std::string element : {"parent", "child", "visual", "collision", "inertial"}) {
    if (head.find("<" + element + " ") == std::string::npos && head.find("<" + element + ">") == std::string::npos) {
      continue;
    }
    throw cli::UsageError("--out: '" + out + "' exists and is a URDF (it has <" + element + "> elements), not an " +
                          "SRDF: not replaced");
  }
  // A URDF of bare links has none of those (an adversarial review replaced one); its links are
  // children of <robot>, where an SRDF's stand inside a <group>.
  TiXmlDocument document;
  if (document.LoadFile(out.c_str()) && document.RootElement() != nullptr &&
      std::string(document.RootElement()->Value()) == "robot") {
    for (const char* element : {"link", "joint"}) {
      if (document.RootElement()->FirstChildElement(element) != nullptr) {
        throw cli::UsageError("--out: '" + out + "' exists and is a URDF (its <robot> has <" + element +
                              "> elements of its own), not an SRDF: not replaced");
      }
    }
  }
}

/// Returns nullopt after printing the help.
std::optional<SrdfArguments> parseArguments(const std::vector<std::string>& args) {
  cli::CommandLine line("adsd srdf", kSynopsis, kDescription, kDetails);
  line.options()
      ("out", cli::value("ROBOT.srdf"), "the SRDF file to write (required)")
      ("states", cli::value("N"), "random joint states to test every pair in (default 10000, MoveIt's)")
      ("seed", cli::value("S"), "seed of the random states (default 1)")
      ("no-default", "keep the pairs in contact in the default pose checked (reason Default)")
      ("never", "also disable the pairs in contact in no state (reason Never; a guess, see above)")
      ("package-path", cli::values("DIR"),
       "where package://NAME/... mesh names are looked for, as DIR/NAME/... then DIR/...; may repeat");
  line.positional("robot");
  const std::optional<cli::Arguments> given = line.parse(args);
  if (!given) return std::nullopt;
  SrdfArguments a;
  const std::vector<std::string> robots = given->texts("robot");
  if (robots.empty()) throw cli::UsageError("expected the robot's URDF file");
  if (robots.size() > 1) throw cli::UsageError("more than one URDF file ('" + robots[0] + "', '" + robots[1] + "')");
  a.urdf = robots.front();
  const std::optional<std::string> out = given->outputFile("out");
  if (!out) throw cli::UsageError("--out ROBOT.srdf is required");
  a.out = *out;
  cli::requireDistinctFile("--out", a.out, {{"the URDF file", a.urdf}});
  requireReplaceable(a.out);
  a.states = given->whole("states", 1, kMaxStates).value_or(kDefaultStates);
  a.seed = given->whole("seed").value_or(1);
  a.never = given->has("never");
  a.defaultPose = !given->has("no-default");
  a.packagePath = given->texts("package-path");
  return a;
}

int run(const SrdfArguments& a) {
  const auto started = std::chrono::steady_clock::now();
  const ArmModel model = readUrdf(a.urdf, a.packagePath);
  ArmCollisionPairs pairs(model);
  const std::size_t adjacent = pairs.disabled().size();
  const std::size_t atDefault = a.defaultPose ? disablePairsInContactAt(model, pairs, defaultJointVector(model)) : 0;
  const PairSamplingResult found = disablePairsBySampling(
      model, pairs, a.states, a.seed, a.never ? NeverInContact::disable : NeverInContact::keep);
  writeSrdf(model, pairs, a.out);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();

  std::size_t withGeometry = 0;
  for (const ArmLink& link : model.links) withGeometry += link.collision ? 1 : 0;
  if (withGeometry < 2) {
    std::cerr << "adsd srdf: warning: " << a.urdf << ": " << withGeometry
              << " link(s) with <collision> geometry: no pair of links to check or leave unchecked\n";
  }
  std::cout << model.name << ": " << model.links.size() << " links, " << withGeometry
            << " with collision geometry, " << model.dof() << " joints to sample\n";
  for (const ArmCollisionPairs::Disabled& d : pairs.disabled()) {
    if (d.reason == "Default" || d.reason == "Always") {
      std::cout << (d.reason == "Default" ? "  in contact in the default pose: '" : "  in contact in every state: '")
                << model.links[d.a].name << "' and '" << model.links[d.b].name << "'\n";
    }
  }
  const std::size_t left = pairs.enabledPairs().size();
  std::cout << "pairs       " << adjacent + atDefault + found.pairsTested << " between links with geometry: "
            << adjacent << " adjacent, " << atDefault << " in contact in the default pose"
            << (a.defaultPose ? "" : " (--no-default: not looked for)") << ", " << found.alwaysInContact
            << " in contact in all " << found.states << " states, "
            << found.neverInContact << " in none"
            << (a.never ? " (disabled: --never)" : " (still checked; --never disables them)") << '\n'
            << "checked     " << left << " pairs\n"
            << "written     " << a.out << " (" << pairs.disabled().size() << " <disable_collisions>, "
            << std::fixed << std::setprecision(1) << seconds << " s)\n";
  return 0;
}

}  // namespace

int srdfCommand(const std::vector<std::string>& args) {
  return reportingErrors("adsd srdf", [&] {
    const std::optional<SrdfArguments> a = parseArguments(args);
    return a ? run(*a) : 0;
  });
}

}  // namespace adsd::app
