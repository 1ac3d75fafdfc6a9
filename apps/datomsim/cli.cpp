// The command line as a function: `datomsim` calls it with the built-in programs, a researcher's
// executable with its own programs added (datomsim/main.h).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/registry.h"
#include "commands.h"
#include "datomsim/main.h"

namespace datomsim {

namespace app {

namespace {

size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The name among `names` nearest `word` (edit distance at most 2), or empty.
std::string nearest(std::string_view word, const std::vector<std::string>& names) {
  std::string best;
  size_t bestDistance = 3;
  for (const std::string& name : names) {
    if (const size_t d = editDistance(word, name); d < bestDistance) {
      bestDistance = d;
      best = name;
    }
  }
  return best;
}

}  // namespace

// "; did you mean \"run\"?" for the subcommand nearest a mistyped word (edit distance at most 2),
// else the list of subcommands.
std::string nearestSubcommand(const CLI::App& app, std::string_view word) {
  std::vector<std::string> names;
  for (const CLI::App* command : app.get_subcommands({})) names.push_back(command->get_name());
  if (const std::string best = nearest(word, names); !best.empty()) {
    return fmt::format("; did you mean \"{}\"?", best);
  }
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  return "; the subcommands are " + list;
}

// The first word of the command line that looks like a long option and that neither the
// subcommands it names nor their parents know, with the nearest one they do: "unknown option
// --tiemout for run; did you mean --timeout?". CLI11 would say "--program is required" first, or
// only that the word was not expected.
std::optional<std::string> unknownOption(const CLI::App& app, int argc, char** argv) {
  std::vector<const CLI::App*> chain = {&app};
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word == "--") break;
    if (word.starts_with("-")) continue;
    for (const CLI::App* command : chain.back()->get_subcommands({})) {
      if (command->get_name() == word) {
        chain.push_back(command);
        break;
      }
    }
  }
  std::vector<std::string> known;
  for (const CLI::App* command : chain) {
    for (const CLI::Option* option : command->get_options({})) {
      for (const std::string& name : option->get_lnames()) known.push_back("--" + name);
    }
  }
  for (int i = 1; i < argc; ++i) {
    const std::string_view word = argv[i];
    if (word == "--") break;
    if (!word.starts_with("--")) continue;
    const std::string name(word.substr(0, word.find('=')));
    if (std::find(known.begin(), known.end(), name) != known.end()) continue;
    std::string path;
    for (size_t k = 1; k < chain.size(); ++k)
      path += (path.empty() ? "" : " ") + chain[k]->get_name();
    const std::string best = nearest(name, known);
    return fmt::format("unknown option {}{}{}", name, path.empty() ? "" : " for " + path,
                       best.empty() ? "" : fmt::format("; did you mean {}?", best));
  }
  return std::nullopt;
}

}  // namespace app

int main(int argc, char** argv, std::vector<ProgramEntry> programs) {
  // A reader that quits (datomsim ... | head) makes a write fail with EPIPE, which the outputs
  // report naming themselves, rather than a signal that kills the process without a word.
  std::signal(SIGPIPE, SIG_IGN);
  if (const Status names = algorithms::checkAdded(programs); !names.ok()) {
    fmt::print(stderr, "datomsim: error: {}\n", names.error());
    return 1;
  }
  CLI::App app{
      "datomsim: a simulator for Datoms, deformable modular robots in the FCC lattice.\n"
      "Run `datomsim SUBCOMMAND --help` for the options of each subcommand."};
  // Help and errors name the executable as the user called it.
  app.name(argc > 0 && argv[0] ? std::filesystem::path(argv[0]).filename().string() : "datomsim");
  app.require_subcommand(1);
  app.set_version_flag("--version", "datomsim 0.1.0");
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet,
               "Say nothing but errors: no \"wrote FILE\" lines and no notes on standard error");
  // --quiet may come after the subcommand too.
  app.fallthrough();
  // What the subcommands tell a person besides errors; it outlives their callbacks, and takes
  // --quiet before any of them runs: CLI11 runs them once the whole line is parsed.
  frontend::Reporter reporter;
  app.parse_complete_callback([&quiet, &reporter] { reporter = frontend::Reporter(quiet); });
  app::addGeometryCommand(app);
  app::addSceneCommands(app, reporter);
  app::addMotionCommands(app, reporter);
  app::addCompareCommand(app, reporter);
  app::addRunCommand(app, reporter, programs);
  app::addPlanCommand(app, reporter);
  app::addLoadsCommand(app, reporter);
  app::addDemoCommand(app, reporter);
  app::addViewCommand(app, reporter);
  app::addVideoCommand(app, reporter);
  app::addSweepCommand(app, reporter);
  app::addMeshCommand(app, reporter);
  app::addActuatorsCommand(app, reporter);
  app::addStudioCommand(app);
  app::addCompletionCommand(app);

  // A first word that names no subcommand: say so, and which one was meant.
  const auto commands = app.get_subcommands({});
  if (argc > 1 && argv[1][0] != '-' &&
      std::none_of(commands.begin(), commands.end(),
                   [&](const CLI::App* command) { return command->get_name() == argv[1]; })) {
    fmt::print(stderr, "datomsim: error: unknown subcommand \"{}\"{}\n", argv[1],
               app::nearestSubcommand(app, argv[1]));
    return 1;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // Help and version exit 0; every other mistake on the command line exits 1 with one line,
    // as any bad input does (CLI11's own codes, 100 and up, would say nothing more).
    if (error.get_exit_code() == 0) return app.exit(error);
    if (const auto unknown = app::unknownOption(app, argc, argv)) {
      fmt::print(stderr, "datomsim: error: {}\nRun with --help for more information.\n", *unknown);
      return 1;
    }
    fmt::print(stderr, "datomsim: error: {}\nRun with --help for more information.\n",
               error.what());
    return 1;
  } catch (const frontend::UsageError& error) {
    fmt::print(stderr, "datomsim: error: {}\n", error.what());
    return 1;
  } catch (const frontend::CheckFailed& error) {
    fmt::print(stderr, "datomsim: {}\n", error.what());
    return 1;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "datomsim: error: out of memory\n");
    return 1;
  } catch (const std::exception& error) {
    // A researcher's program that throws (a parameter it did not declare, say) ends the run
    // with its message rather than an abort.
    fmt::print(stderr, "datomsim: error: {}\n", error.what());
    return 1;
  }
  // What a subcommand printed itself (a table, an info line) reached its reader, or says why not.
  if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
    fmt::print(stderr, "datomsim: error: cannot write to standard output: {}\n",
               std::strerror(errno));
    return 1;
  }
  return 0;
}

}  // namespace datomsim
