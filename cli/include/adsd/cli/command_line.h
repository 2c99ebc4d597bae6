#pragma once
/// \file
/// \brief One program's command line, read through Boost.Program_options the same way in every
/// program here (the adsd subcommands, the bench programs, adsd_stress).
///
/// - `-h` or `--help` anywhere prints the synopsis, the description, the options and the details
///   on stdout, and the program exits 0 (parse() returns nullopt).
/// - A bad command line throws UsageError; reportUsageError() prints it as one line on stderr,
///   "PROGRAM: error: WHAT (PROGRAM --help)", and the program exits 2.
/// - Options are spelled in full (no guessing from a prefix, so that a script's "--t" is an error
///   rather than whichever option starts with t); a value follows as "--time 5" or "--time=5"; an
///   option that takes one value given twice is an error rather than a silent choice.
/// - Values stay text until Arguments converts them (numbers.h), so that every number is read
///   alike in every locale and every message names the option and the text given.
///
/// Use:
/// \code
///   adsd::cli::CommandLine line("bench_x", "bench_x [--poses N] [MESH...]", "What bench_x measures.");
///   line.options()
///       ("poses", adsd::cli::value("N"), "poses per scene (default 60)")
///       ("quick", "a short run");
///   line.positional("mesh");
///   return adsd::cli::runProgram(line, argc, argv, [](const adsd::cli::Arguments& given) {
///     const std::uint64_t poses = given.whole("poses", 1, 1000000).value_or(60);
///     ...
///   });
/// \endcode

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iosfwd>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <boost/program_options.hpp>

#include "adsd/cli/numbers.h"
#include "adsd/cli/usage_error.h"

namespace adsd::cli {

namespace po = boost::program_options;

/// \brief An option's value, shown as \p name in the help ("--time SECONDS").
po::typed_value<std::string>* value(const char* name);
/// \brief An option that may be given several times; its values are kept in order.
po::typed_value<std::vector<std::string>>* values(const char* name);

/// \brief The options and arguments given, with conversions that name the option on error.
class Arguments {
 public:
  explicit Arguments(po::variables_map map) : map_(std::move(map)) {}

  /// Whether option \p name was given (flags, and options with a value).
  bool has(const std::string& name) const { return map_.count(name) > 0; }
  /// The value of option \p name; nullopt when it was not given.
  std::optional<std::string> text(const std::string& name) const;
  /// Option \p name as a file the program will write once its work is done: checked now, so that
  /// a run of minutes does not end in "cannot write". Throws UsageError when the name is empty,
  /// names a directory, a device, a pipe or a socket, or its directory does not exist or cannot
  /// be written.
  std::optional<std::string> outputFile(const std::string& name) const;
  /// Every value of a repeated option, or the positional arguments (CommandLine::positional).
  std::vector<std::string> texts(const std::string& name) const;
  /// Option \p name as a whole number in [\p min, \p max] (numbers.h's parseWhole).
  std::optional<std::uint64_t> whole(const std::string& name, std::uint64_t min = 0,
                                     std::uint64_t max = std::numeric_limits<std::uint64_t>::max()) const;
  /// Option \p name as a finite number in \p range (numbers.h's parseReal).
  std::optional<double> real(const std::string& name, const RealInterval& range = {}) const;
  /// Option \p name, which must be one of \p choices ("--NAME: expected a, b or c, got 'x'").
  std::optional<std::string> choice(const std::string& name, std::initializer_list<std::string_view> choices) const;

 private:
  po::variables_map map_;
};

/// \brief Throws UsageError when file \p output, which option \p option names, is one of \p others
/// (the same file by another name too): a command's output must replace neither its input nor
/// another of its outputs (`adsd view p.cfg --html p.cfg` replaced the problem file with a page).
/// \p others holds (what, file) pairs, `what` naming the other in the message.
void requireDistinctFile(const std::string& option, const std::string& output,
                         const std::vector<std::pair<std::string, std::string>>& others);

/// \brief Whether \p file, through any symbolic links of its directories and of itself, lies in
/// /dev, /proc or /sys: a name such as /dev/stdout stands for a stream, and an output renamed
/// into place there would replace the system's link with a plain file.
bool inSystemTree(const std::string& file);

/// \brief A program's (or subcommand's) options, its help, and the parsing of its arguments.
class CommandLine {
 public:
  /// \p program as typed ("adsd plan", "bench_scenes"), for messages; \p synopsis the usage line
  /// without "usage: " (may span lines); \p description a paragraph under it; \p details text
  /// printed after the options (defaults, formats, exit status), may be empty.
  CommandLine(std::string program, std::string synopsis, std::string description, std::string details = {});

  /// Declares options, Boost's way: `options()("name", cli::value("X"), "what")("flag", "what")`.
  /// `--help` is declared already.
  po::options_description_easy_init options() { return options_.add_options(); }
  /// Arguments that are not options go, in order, to Arguments::texts(\p name).
  void positional(const std::string& name);

  /// Parses \p args (without the program's name). Prints the help and returns nullopt when they
  /// ask for it; throws UsageError when they cannot be read.
  std::optional<Arguments> parse(const std::vector<std::string>& args) const;
  void printHelp(std::ostream& out) const;
  const std::string& program() const { return program_; }

 private:
  std::string program_;
  std::string synopsis_;
  std::string description_;
  std::string details_;
  po::options_description options_;
  po::options_description help_;
  std::optional<std::string> positional_;
};

/// \brief Prints \p error as one line on stderr, "PROGRAM: error: WHAT (PROGRAM --help)", and
/// returns kUsageExitStatus.
int reportUsageError(const std::string& program, const UsageError& error);

/// \brief For a program's main(): parses argv[1..] with \p line and runs \p run on them. Returns
/// 0 after the help, reportUsageError() for a UsageError (from the parsing or from \p run), and
/// otherwise what \p run returns; other exceptions pass through to the caller.
int runProgram(const CommandLine& line, int argc, char** argv, const std::function<int(const Arguments&)>& run);

}  // namespace adsd::cli
