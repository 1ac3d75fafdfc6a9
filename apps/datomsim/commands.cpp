#include "commands.h"

namespace datomsim::app {

void addExample(CLI::App& command, const std::string& arguments) {
  command.footer("\nExample:\n  datomsim " + arguments);
}

void addOutputOption(CLI::App& command, std::string& out) {
  command.add_option("--out", out,
                     "Write the JSON to this file (without it, or with \"-\": standard output)");
}

}  // namespace datomsim::app
