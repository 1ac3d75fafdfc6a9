// `completion bash|zsh`: a shell completion script made from the command line's own definition,
// so that it knows every subcommand, option and choice of this build (a researcher's executable
// included, with its programs).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "commands.h"

namespace datomsim::app {

namespace {

// What the script knows of one command: its path ("", "generate", "generate box"), the
// subcommands under it, its options, and the choices of the options that take one of a list.
struct CommandWords {
  std::vector<std::string> subcommands;
  std::vector<std::string> options;
  std::map<std::string, std::string> choices;  // option -> "a b c"
};

// The list of an IsMember check, as CLI11 names it in the option's type: "TEXT:{a,b,c}".
std::string choicesOf(const CLI::Option& option) {
  static const std::regex kList(R"(\{([^{}]*)\})");
  std::smatch list;
  const std::string type = option.get_type_name();
  if (!std::regex_search(type, list, kList)) return "";
  std::string words = list[1];
  for (char& c : words) {
    if (c == ',') c = ' ';
  }
  return words;
}

void collect(const CLI::App& command, const std::string& path,
             std::map<std::string, CommandWords>& into) {
  CommandWords& words = into[path];
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& name : option->get_lnames()) {
      words.options.push_back("--" + name);
      if (const std::string choices = choicesOf(*option); !choices.empty()) {
        words.choices["--" + name] = choices;
      }
    }
    for (const std::string& name : option->get_snames()) words.options.push_back("-" + name);
  }
  for (const CLI::App* sub : command.get_subcommands({})) {
    words.subcommands.push_back(sub->get_name());
    collect(*sub, path.empty() ? sub->get_name() : path + " " + sub->get_name(), into);
  }
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& word : words) out += (out.empty() ? "" : " ") + word;
  return out;
}

// The bash script; zsh runs it through bashcompinit.
std::string bashScript(const CLI::App& app, const std::string& name) {
  std::map<std::string, CommandWords> commands;
  collect(app, "", commands);
  std::string known, subcommands, options, choices;
  for (const auto& [path, words] : commands) {
    known += fmt::format("    \"{}\") return 0 ;;\n", path);
    if (!words.subcommands.empty()) {
      subcommands += fmt::format("    \"{}\") echo \"{}\" ;;\n", path, join(words.subcommands));
    }
    options += fmt::format("    \"{}\") echo \"{}\" ;;\n", path, join(words.options));
    for (const auto& [option, list] : words.choices) {
      choices += fmt::format("    \"{} {}\") echo \"{}\" ;;\n", path, option, list);
    }
  }
  const std::string function = "_" + std::regex_replace(name, std::regex("[^A-Za-z0-9_]"), "_");
  return fmt::format(R"script(# {name} completion for bash (and zsh, through bashcompinit); made by
# `{name} completion bash` from this build's own command line. Load it with
#   source <({name} completion bash)
# or save it where bash-completion looks (~/.local/share/bash-completion/completions/{name}).
{f}_known() {{
  case "$1" in
{known}  esac
  return 1
}}
{f}_subcommands() {{
  case "$1" in
{subcommands}  esac
}}
{f}_options() {{
  case "$1" in
{options}  esac
}}
{f}_choices() {{
  case "$1" in
{choices}  esac
}}
{f}() {{
  local cur="${{COMP_WORDS[COMP_CWORD]}}" previous="${{COMP_WORDS[COMP_CWORD-1]}}" words_path="" i word next
  # The subcommands typed so far, skipping options and their values (not named "path": zsh ties
  # that name to PATH).
  for ((i = 1; i < COMP_CWORD; i++)); do
    word="${{COMP_WORDS[i]}}"
    [[ "$word" == -* ]] && continue
    next="${{words_path:+$words_path }}$word"
    {f}_known "$next" && words_path="$next"
  done
  local choices
  choices="$({f}_choices "$words_path $previous")"
  if [[ -n "$choices" ]]; then
    COMPREPLY=($(compgen -W "$choices" -- "$cur"))
  elif [[ "$cur" == -* ]]; then
    COMPREPLY=($(compgen -W "$({f}_options "$words_path")" -- "$cur"))
  else
    COMPREPLY=($(compgen -W "$({f}_subcommands "$words_path")" -- "$cur") $(compgen -f -- "$cur"))
  fi
}}
complete -o filenames -F {f} {name}
)script",
                     fmt::arg("name", name), fmt::arg("f", function), fmt::arg("known", known),
                     fmt::arg("subcommands", subcommands), fmt::arg("options", options),
                     fmt::arg("choices", choices));
}

}  // namespace

void addCompletionCommand(CLI::App& app) {
  auto shell = std::make_shared<std::string>();
  CLI::App* command = app.add_subcommand(
      "completion", "Print a shell completion script for bash or zsh (docs/shell-completion.md)");
  command->add_option("shell", *shell, "bash or zsh")
      ->required()
      ->check(CLI::IsMember({"bash", "zsh"}));
  addExample(*command, "completion bash > ~/.local/share/bash-completion/completions/datomsim");
  CLI::App* root = &app;
  command->callback([shell, root] {
    const std::string script = bashScript(*root, root->get_name());
    if (*shell == "bash") {
      fmt::print("{}", script);
    } else {
      fmt::print(
          "# zsh: bash's completion, read through bashcompinit. Load it with\n"
          "#   source <({0} completion zsh)\n"
          "(( $+functions[compdef] )) || {{ autoload -U +X compinit && compinit; }}\n"
          "autoload -U +X bashcompinit && bashcompinit\n{1}",
          root->get_name(), script);
    }
  });
}

}  // namespace datomsim::app
