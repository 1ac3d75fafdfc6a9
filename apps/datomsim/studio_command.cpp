// `studio`: a live simulator in the browser, served on this machine (docs/studio.md).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "commands.h"
#include "export/viewer_page.h"
#include "io/scene_file.h"
#include "scene/box.h"
#include "studio/page.h"
#include "studio/server.h"
#include "studio/session.h"

namespace datomsim::app {

namespace {

struct StudioArguments {
  std::string scene, host = "127.0.0.1", viewerJs, requests;
  int port = 8600;
};

// The scene opened without one: a floor of 8 x 8 modules in a grid of 12 x 12 x 8.
io::Scene emptyFloor() {
  scene::BoxOptions options;
  options.gridSize = geometry::Cell{12, 12, 8};
  options.color = Color{128, 128, 128};
  io::Scene scene;
  scene.world = unwrap(scene::box({8, 8, 1}, options));
  return scene;
}

// Without a server: the requests of a file, one per line, each reply printed on a line of its own.
void answerRequests(io::Scene scene, const std::string& name, const std::string& path,
                    const std::string& viewerJs) {
  std::ifstream file;
  if (path != "-") {
    file.open(path);
    if (!file) throw UsageError("--requests " + path + ": cannot open");
  }
  std::istream& input = path == "-" ? std::cin : file;
  studio::Session session(std::move(scene), name);
  // The page of a run needs the viewer's script; without one, only that request is refused.
  const auto here =
      viewerJs.empty() ? exporting::executableDirectory() : Result<std::filesystem::path>("");
  session.setViewerBundle(here ? exporting::loadViewerBundle(viewerJs, *here)
                               : Result<std::string>(Error{here.error()}));
  std::string line;
  while (std::getline(input, line)) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    std::printf("%s\n", session.handle(line).c_str());
  }
  std::fflush(stdout);
}

bool isLoopback(const std::string& host) {
  return host == "127.0.0.1" || host == "::1";
}

void runStudio(const StudioArguments& arguments) {
  if (arguments.port < 0 || arguments.port > 65535) {
    throw UsageError(
        fmt::format("--port {}: a port is 0 to 65535 (0: any free one)", arguments.port));
  }
  io::Scene scene = arguments.scene.empty() ? emptyFloor() : unwrap(io::readScene(arguments.scene));
  const std::string name = arguments.scene.empty() ? "a floor" : arguments.scene;
  if (!arguments.requests.empty())
    return answerRequests(std::move(scene), name, arguments.requests, arguments.viewerJs);
  const std::filesystem::path here =
      arguments.viewerJs.empty() ? unwrap(exporting::executableDirectory()) : "";
  const std::string bundle = unwrap(exporting::loadViewerBundle(arguments.viewerJs, here));

  studio::Session session(std::move(scene), name);
  session.setViewerBundle(bundle);
  studio::ServerOptions options;
  options.host = arguments.host;
  options.port = uint16_t(arguments.port);
  // Another address than this machine's own: a token keeps the others on the network out.
  if (!isLoopback(arguments.host)) options.token = studio::newToken();
  options.page = studio::studioPage(bundle);
  const std::string token = options.token;
  auto server = unwrap(studio::Server::listen(session, std::move(options)));
  const std::string host =
      arguments.host.find(':') != std::string::npos ? "[" + arguments.host + "]" : arguments.host;
  std::printf("studio at http://%s:%u/%s\n", host.c_str(), unsigned(server->port()),
              token.empty() ? "" : ("?token=" + token).c_str());
  std::printf("(Ctrl-C ends it)\n");
  std::fflush(stdout);
  server->run();
}

}  // namespace

void addStudioCommand(CLI::App& app) {
  auto arguments = std::make_shared<StudioArguments>();
  CLI::App* command =
      app.add_subcommand("studio",
                         "A live simulator in the browser: edit the scene, run a program, step "
                         "and inspect it (docs/studio.md)");
  command->add_option("scene", arguments->scene,
                      "Scene file to open (.xml or .json; default: a floor of 8 x 8 modules)");
  command->add_option("--port", arguments->port, "Port to serve on (0: any free one)")
      ->capture_default_str();
  command
      ->add_option("--host", arguments->host,
                   "Address to serve on; another than 127.0.0.1 asks every page for an access "
                   "token, printed at the start")
      ->capture_default_str();
  command->add_option("--viewer-js", arguments->viewerJs,
                      "The viewer script to serve (default: viewer.bundle.js next to the binary)");
  command->add_option("--requests", arguments->requests,
                      "Serve nothing: answer the requests of this file (\"-\": standard input), "
                      "one JSON object a line, each reply on a line of its own (docs/studio.md)");
  addExample(*command, "studio scenes/paper-arch-hole1.json --port 8600");
  command->callback([arguments] { runStudio(*arguments); });
}

}  // namespace datomsim::app
