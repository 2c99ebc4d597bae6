// `adsd distance MESH_A MESH_B [--poses FILE|-] [--csv] [--abs-tol X] [--rel-tol X]
//                [--threshold D] [--cap D] [--path auto|tree|scratch]`
//
// The distance between two mesh files (OBJ, OFF, PLY, STL read in double; any other format assimp
// reads, in float; node transforms applied, only triangles kept). Without --poses both meshes stay at identity and a readable summary is printed;
// with --poses every line of the pose file is one query. Everything is read and checked before
// the first query runs, and the output is written only once all queries are done, so that bad
// input leaves one line on stderr, exit status 2, and nothing on stdout. Many poses of the same
// two rigid meshes are answered as a planner would, on sub-mesh trees built once; a few, from
// scratch by the paper's stages (which need no preprocessing).

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "adsd/cli/command_line.h"
#include "adsd/cli/numbers.h"
#include "adsd/distance.h"
#include "adsd/error.h"
#include "adsd/io/load_mesh.h"
#include "adsd/io/pose_file.h"
#include "commands.h"

namespace adsd::app {

namespace {

constexpr const char* kSynopsis =
    "adsd distance MESH_A MESH_B [--poses FILE|-] [--csv] [--abs-tol X] [--rel-tol X]\n"
    "                     [--threshold D] [--cap D] [--path auto|tree|scratch]";

constexpr const char* kDescription =
    "Minimum distance between two triangle meshes (OBJ, OFF, PLY, STL, and any other file assimp\n"
    "reads: COLLADA, glTF, 3DS, ...; scene node transforms are applied and only triangles kept).";

constexpr const char* kDetails =
    "Without --poses both meshes are at identity and a readable summary is printed. With --poses,\n"
    "each line of FILE (- for stdin) is one query: 14 numbers, tx ty tz qw qx qy qz for mesh A and\n"
    "then for mesh B (each pose maps mesh coordinates to the world; quaternions of unit norm);\n"
    "'#' starts a comment; at most 1000000 poses per file. Witness points are in the world frame.\n"
    "\n"
    "Query mode: exact by default; --abs-tol/--rel-tol (together or alone) return an interval\n"
    "[lower, upper] within the tolerance; --threshold D only decides whether the distance exceeds\n"
    "D; --cap D reports distances beyond D as '>= D'. Give at most one mode.\n"
    "\n"
    "Precision of the mesh files, by extension:\n"
    "  .obj .off, ASCII .ply and .stl   every coordinate as the double nearest its text: 17\n"
    "                                   significant digits read back bit for bit\n"
    "  binary .ply, double properties   the doubles as stored\n"
    "  binary .ply, float properties    float32 as stored (about 7 digits)\n"
    "  binary .stl                      float32 as stored (the format has nothing else)\n"
    "  .dae and the rest (via assimp)   float32: assimp stores coordinates in float\n"
    "Coordinates and pose translations beyond +-1e75 are refused (squared lengths would overflow).\n"
    "\n"
    "CSV columns: distance,lower,upper,status,ax,ay,az,bx,by,bz,micros, then line (the pose-file\n"
    "line, 0 without --poses), triangle_a, triangle_b, the query's counters and its path (tree or\n"
    "scratch). Witness fields are empty when the query needed no triangle pair to prove its status.\n"
    "\n"
    "Path: with --path auto (the default), a pose file of at least 16 lines is answered on sub-mesh\n"
    "trees built once for both meshes (what a planner keeps between queries), fewer poses from\n"
    "scratch by the paper's stages (no preprocessing). A query from scratch that goes over a\n"
    "budget of about twice what building the trees costs is finished on trees, and with auto the\n"
    "queries after it use them too. The summary, and the last line of the line-per-query output,\n"
    "say which path ran and what building the trees took.\n"
    "\n"
    "Exit status: 0 done, 1 the output could not be written, 2 bad input or usage (one line on\n"
    "stderr naming the file and line).\n";

/// Poses from which `--path auto` builds trees: building both trees costs as much as a dozen or
/// a few dozen queries from scratch on the same meshes (the build grows as n log n in the
/// triangles, a query from scratch about as n), so from here on the trees pay for themselves,
/// and their queries are then many times cheaper (docs/commands.md says how to measure both).
constexpr std::size_t kPosesForTrees = 16;

enum class QueryPath { automatic, tree, scratch };

struct DistanceArguments {
  std::string meshA;
  std::string meshB;
  std::optional<std::string> poses;
  bool csv = false;
  DistanceOptions options;
  QueryPath path = QueryPath::automatic;
};

/// Shortest text that reads back as the same double ("inf" for infinity).
std::string number(double value) { return cli::shortestText(value); }

/// The query mode from the flags; conflicting modes are an error rather than a silent choice.
DistanceOptions queryOptions(const cli::Arguments& given) {
  const bool tolerance = given.has("abs-tol") || given.has("rel-tol");
  const bool threshold = given.has("threshold");
  const bool cap = given.has("cap");
  if (int(tolerance) + int(threshold) + int(cap) > 1) {
    std::vector<std::string> named;
    for (const char* flag : {"abs-tol", "rel-tol", "threshold", "cap"}) {
      if (given.has(flag)) named.push_back(std::string("--") + flag);
    }
    std::string list = named.front();
    for (std::size_t i = 1; i < named.size(); ++i) list += (i + 1 == named.size() ? " and " : ", ") + named[i];
    throw cli::UsageError(list + " select different query modes (tolerance, threshold, cap); give at most one");
  }
  const cli::RealInterval nonNegative = cli::RealInterval::atLeast(0.0);
  if (tolerance) {
    const double absTol = given.real("abs-tol", nonNegative).value_or(0.0);
    const double relTol = given.real("rel-tol", nonNegative).value_or(0.0);
    return DistanceOptions::withTolerance(absTol, relTol);
  }
  if (threshold) return DistanceOptions::aboveThreshold(*given.real("threshold", nonNegative));
  if (cap) return DistanceOptions::cappedAt(*given.real("cap", cli::RealInterval::above(0.0)));
  return DistanceOptions::exactDistance();
}

/// Returns nullopt after printing the help.
std::optional<DistanceArguments> parseArguments(const std::vector<std::string>& args) {
  cli::CommandLine line("adsd distance", kSynopsis, kDescription, kDetails);
  line.options()
      ("poses", cli::value("FILE"), "one query per line of FILE (- reads stdin)")
      ("csv", "CSV: a header, then one row per query")
      ("abs-tol", cli::value("X"), "tolerance mode: absolute slack X >= 0")
      ("rel-tol", cli::value("X"), "tolerance mode: slack X >= 0 relative to the upper bound")
      ("threshold", cli::value("D"), "threshold mode: only decide whether distance > D")
      ("cap", cli::value("D"), "cap mode: distances beyond D reported as >= D")
      ("path", cli::value("P"), "auto (default), tree (sub-mesh trees built once) or scratch (the paper's stages)");
  line.positional("mesh");
  const std::optional<cli::Arguments> given = line.parse(args);
  if (!given) return std::nullopt;
  const std::vector<std::string> meshes = given->texts("mesh");
  if (meshes.size() != 2) {
    throw cli::UsageError("expected two mesh files (MESH_A MESH_B), got " + std::to_string(meshes.size()));
  }
  DistanceArguments a;
  a.meshA = meshes[0];
  a.meshB = meshes[1];
  a.poses = given->text("poses");
  a.csv = given->has("csv");
  a.options = queryOptions(*given);
  const std::string path = given->choice("path", {"auto", "tree", "scratch"}).value_or("auto");
  a.path = path == "tree" ? QueryPath::tree : path == "scratch" ? QueryPath::scratch : QueryPath::automatic;
  return a;
}

/// Poses a file may hold: a query's pose, result and output line take about 700 bytes, all kept
/// until the last query is answered (nothing is printed before every line is read and good), so
/// an endless stream of poses on stdin took all the memory.
constexpr std::size_t kMaxPoses = 1000000;

std::vector<io::PosePair> readPoses(const std::string& source) {
  std::vector<io::PosePair> poses;
  if (source == "-") {
    poses = io::readPoseFile(std::cin, "stdin", kMaxPoses);
  } else {
    std::error_code ec;
    if (!std::filesystem::exists(source, ec)) throw InputError(source + ": no such file");
    if (std::filesystem::is_directory(source, ec)) throw InputError(source + ": is a directory, not a pose file");
    // Read line by line: /dev/zero is one line without end, which filled the memory (stdin, `-`,
    // is for pipes).
    if (!std::filesystem::is_regular_file(source, ec)) {
      throw InputError(source + ": is a device, a pipe or a socket, not a pose file (give it as - on stdin)");
    }
    std::ifstream in(source);
    if (!in) throw InputError(source + ": cannot be opened for reading");
    poses = io::readPoseFile(in, source, kMaxPoses);
  }
  if (poses.empty()) {
    throw InputError((source == "-" ? std::string("stdin") : source) +
                     ": no poses (only comments or blank lines)");
  }
  return poses;
}

struct Query {
  int line = 0;  ///< pose-file line, 0 without --poses
  DistanceResult result;
  double micros = 0.0;
  bool onTrees = false;  ///< answered on the trees the command built (else from scratch)
};

std::string describeMode(const DistanceOptions& o) {
  switch (o.mode) {
    case QueryMode::exact: return "exact";
    case QueryMode::tolerance: return "tolerance (absolute " + number(o.absTolerance) + ", relative " + number(o.relTolerance) + ")";
    case QueryMode::threshold: return "threshold " + number(o.threshold) + " (is the distance above it?)";
    case QueryMode::cap: return "cap " + number(o.cap) + " (distances beyond it reported as >= cap)";
  }
  return "?";
}

std::string point(const Vec3& p) { return number(p.x()) + " " + number(p.y()) + " " + number(p.z()); }

bool hasWitnesses(const DistanceResult& r) { return r.triangleA >= 0 && r.triangleB >= 0; }

std::string counters(const DistanceCounters& c) {
  std::ostringstream out;
  out << "depth " << c.maxDepth << ", sub-mesh pairs " << c.subMeshPairs << ", rejected by bounds "
      << c.pairsRejectedByBounds << ", hashed " << c.pairsHashed << ", split " << c.pairsSplit
      << ", triangles hashed " << c.trianglesHashed << ", triangle pairs tested " << c.trianglePairsTested
      << ", GJK runs " << c.gjkCalls << " (" << c.gjkIterations << " iterations, at most " << c.gjkMaxIterations
      << ")";
  if (c.hashRestarts != 0) out << ", hashing restarts " << c.hashRestarts;
  if (c.treeAbandoned != 0) out << "; the trees could not tell the triangles apart: finished from scratch";
  if (c.scratchAbandoned != 0) out << "; over the budget from scratch: finished on trees built for the query";
  return out.str();
}

std::string micros(double us) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3f", us);
  return text;
}

/// Which path answered the queries, for the summary and the last line of the line output.
struct PathTaken {
  bool trees = false;
  double buildMicros = 0.0;  ///< building both trees (not in any query's time)
  std::size_t scratchQueries = 0;     ///< queries answered before the trees were built
  std::size_t overBudget = 0;         ///< of those, queries finished on trees built for them alone
  std::string describe() const {
    std::string text;
    if (!trees || scratchQueries > 0) {
      text = "from scratch (the paper's stages, no preprocessing)";
      if (overBudget > 0) {
        text += ", " + std::to_string(overBudget) + " of " + std::to_string(scratchQueries) +
                " over the budget and finished on trees built for the query";
      }
      if (!trees) return text;
      text += "; then ";
    }
    char built[96];
    std::snprintf(built, sizeof built, "sub-mesh trees, built once for both meshes in %.3f us", buildMicros);
    return text + built;
  }
};

void writeSummary(std::ostream& out, const DistanceArguments& a, const Mesh& meshA, const Mesh& meshB,
                  const Query& q, const PathTaken& path) {
  const DistanceResult& r = q.result;
  out << "mesh A      " << a.meshA << ": " << meshA.triangleCount() << " triangles, " << meshA.vertices().size()
      << " vertices\n";
  out << "mesh B      " << a.meshB << ": " << meshB.triangleCount() << " triangles, " << meshB.vertices().size()
      << " vertices\n";
  out << "query       " << describeMode(a.options) << ", both meshes at identity\n";
  out << "distance    " << (r.status == DistanceStatus::beyondCap ? ">= " : "") << number(r.distance) << '\n';
  out << "interval    [" << number(r.lower) << ", " << number(r.upper) << "]\n";
  if (hasWitnesses(r)) {
    out << "witness A   " << point(r.witnessA) << "   (world frame, triangle " << r.triangleA << " of A)\n";
    out << "witness B   " << point(r.witnessB) << "   (world frame, triangle " << r.triangleB << " of B)\n";
  } else {
    out << "witnesses   none (no triangle pair was needed to prove the status)\n";
  }
  out << "status      " << toString(r.status) << '\n';
  out << "counters    " << counters(r.counters) << '\n';
  out << "path        " << path.describe() << '\n';
  out << "time        " << micros(q.micros) << " us\n";
}

void writeLine(std::ostream& out, const Query& q) {
  const DistanceResult& r = q.result;
  out << "line " << q.line << ": distance " << (r.status == DistanceStatus::beyondCap ? ">= " : "") << number(r.distance)
      << " in [" << number(r.lower) << ", " << number(r.upper) << "], " << toString(r.status);
  if (hasWitnesses(r)) out << ", A (" << point(r.witnessA) << ") B (" << point(r.witnessB) << ")";
  out << ", " << micros(q.micros) << " us\n";
}

void writeCsvHeader(std::ostream& out) {
  out << "distance,lower,upper,status,ax,ay,az,bx,by,bz,micros,line,triangle_a,triangle_b,max_depth,"
         "sub_mesh_pairs,pairs_rejected_by_bounds,pairs_hashed,pairs_split,triangles_hashed,"
         "triangle_pairs_tested,gjk_calls,gjk_iterations,gjk_max_iterations,tree_abandoned,hash_restarts,"
         "scratch_abandoned,path\n";
}

void writeCsvRow(std::ostream& out, const Query& q) {
  const DistanceResult& r = q.result;
  const DistanceCounters& c = r.counters;
  out << number(r.distance) << ',' << number(r.lower) << ',' << number(r.upper) << ',' << toString(r.status) << ',';
  if (hasWitnesses(r)) {
    const Vec3& wa = r.witnessA;
    const Vec3& wb = r.witnessB;
    out << number(wa.x()) << ',' << number(wa.y()) << ',' << number(wa.z()) << ',' << number(wb.x()) << ','
        << number(wb.y()) << ',' << number(wb.z()) << ',';
  } else {
    out << ",,,,,,";
  }
  out << micros(q.micros) << ',' << q.line << ',' << r.triangleA << ',' << r.triangleB << ',' << c.maxDepth << ','
      << c.subMeshPairs << ',' << c.pairsRejectedByBounds << ',' << c.pairsHashed << ',' << c.pairsSplit << ','
      << c.trianglesHashed << ',' << c.trianglePairsTested << ',' << c.gjkCalls << ',' << c.gjkIterations << ','
      << c.gjkMaxIterations << ',' << c.treeAbandoned << ',' << c.hashRestarts << ',' << c.scratchAbandoned << ','
      << (q.onTrees ? "tree" : "scratch") << '\n';
}

int runDistance(const std::vector<std::string>& args) {
  const std::optional<DistanceArguments> parsed = parseArguments(args);
  if (!parsed) return 0;
  const DistanceArguments& a = *parsed;

  // All input first: both meshes and the whole pose file.
  Mesh meshA = io::loadMesh(a.meshA);
  Mesh meshB = io::loadMesh(a.meshB);
  std::vector<io::PosePair> poses;
  if (a.poses) {
    poses = readPoses(*a.poses);
  } else {
    poses.emplace_back();  // both at identity; line 0
  }

  PathTaken path;
  auto buildTrees = [&] {
    const auto start = std::chrono::steady_clock::now();
    meshA.buildHierarchy();
    meshB.buildHierarchy();
    path.buildMicros = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    path.trees = true;
  };
  if (a.path == QueryPath::tree || (a.path == QueryPath::automatic && poses.size() >= kPosesForTrees)) buildTrees();
  // One scratch for all queries: allocation-free once warm (distance.h).
  DistanceScratch scratch;
  std::vector<Query> queries;
  queries.reserve(poses.size());
  for (const io::PosePair& p : poses) {
    Query q;
    q.line = p.line;
    q.onTrees = path.trees;
    const auto start = std::chrono::steady_clock::now();
    try {
      q.result = distance(meshA, p.a, meshB, p.b, a.options, scratch);
    } catch (const InputError& e) {
      // A pose the core refuses (a translation beyond 1e75, say): name the pose file's line too.
      if (!a.poses) throw;
      throw InputError((*a.poses == "-" ? std::string("stdin") : *a.poses) + ":" + std::to_string(p.line) + ": " +
                       e.what());
    }
    q.micros = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    queries.push_back(q);
    if (!path.trees) {
      ++path.scratchQueries;
      if (q.result.counters.scratchAbandoned != 0) {
        ++path.overBudget;
        // These meshes cost more from scratch than trees cost to build: keep trees for the poses
        // left, unless the trees could not tell the surfaces apart either (treeAbandoned: every
        // query on them would give up and finish from scratch).
        if (a.path == QueryPath::automatic && queries.size() < poses.size() &&
            q.result.counters.treeAbandoned == 0) {
          buildTrees();
        }
      }
    }
  }

  std::ostringstream out;
  if (a.csv) {
    writeCsvHeader(out);
    for (const Query& q : queries) writeCsvRow(out, q);
  } else if (a.poses) {
    for (const Query& q : queries) writeLine(out, q);
    out << "path: " << path.describe() << ", " << queries.size() << " queries\n";
  } else {
    writeSummary(out, a, meshA, meshB, queries.front(), path);
  }
  errno = 0;
  std::cout << out.str() << std::flush;
  if (!std::cout) {
    // The stream keeps no reason; errno holds the failed write's (ENOSPC on /dev/full).
    std::cerr << "adsd distance: error: cannot write the output" << (errno != 0 ? ": " : "")
              << (errno != 0 ? std::strerror(errno) : "") << '\n';
    return 1;
  }
  return 0;
}

}  // namespace

int distanceCommand(const std::vector<std::string>& args) {
  return reportingErrors("adsd distance", [&] { return runDistance(args); });
}

}  // namespace adsd::app
