// `view`: one self-contained HTML page that replays a trace, or shows a scene, in a browser.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <filesystem>

#include "commands.h"
#include "export/viewer_page.h"

namespace datomsim::app {

void addViewCommand(CLI::App& app) {
  struct Arguments {
    std::string input, out, reach, viewerJs, title;
  };
  auto args = std::make_shared<Arguments>();
  CLI::App* command = app.add_subcommand(
      "view",
      "Write one HTML page that replays a trace (or shows a scene) in 3D; it works offline from "
      "disk (docs/viewer.md)");
  command
      ->add_option("input", args->input,
                   "Trace (datomsim run --trace) or scene file (.xml or .json)")
      ->required();
  command->add_option("-o,--out", args->out,
                      "HTML file to write (default: the input's name with .html added, so that a "
                      "scene and its trace, x.json and x.jsonl, give two pages)");
  command->add_option("--reach", args->reach,
                      "A distance map and path to show: the JSON of `datomsim reach --out`");
  command->add_option("--title", args->title,
                      "Title of the page (default: the trace's description)");
  command->add_option("--viewer-js", args->viewerJs,
                      "The viewer script to inline (default: viewer.bundle.js next to the binary)");
  addExample(*command, "view scenes/walkers.json -o walkers.html");
  command->callback([args] {
    const std::filesystem::path input = args->input;
    exporting::ViewerPage page = unwrap(exporting::pageForFile(input));
    if (!args->reach.empty()) {
      page.overlay =
          unwrap(exporting::checkOverlay(unwrap(exporting::readFile(args->reach)), args->reach));
    }
    if (!args->title.empty()) page.title = args->title;

    std::filesystem::path out = args->out;
    // x.json.html, x.jsonl.html: a scene and its trace never write the same page.
    if (out.empty()) out = std::filesystem::path(input.string() + ".html");
    std::error_code error;
    if (std::filesystem::equivalent(out, input, error)) {
      throw UsageError(
          fmt::format("the page {} would overwrite its input; choose another -o", out.string()));
    }
    const std::filesystem::path here =
        args->viewerJs.empty() ? unwrap(exporting::executableDirectory()) : "";
    const std::string bundle = unwrap(exporting::loadViewerBundle(args->viewerJs, here));
    check(exporting::writeViewerPage(out, bundle, page));
    reportWritten(out.string());
  });
}

}  // namespace datomsim::app
