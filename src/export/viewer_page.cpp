#include "export/viewer_page.h"

#include <dlfcn.h>
#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "common/atomic_file.h"
#include "export/trace_check.h"
#include "io/scene_file.h"
#include "record/trace_writer.h"

namespace datomsim::exporting {
namespace {

using Json = nlohmann::json;

// A trace or distance map nests three levels; anything far deeper is refused before a parser or
// printer walks it recursively.
constexpr int kMaxNesting = 32;

// One top-level JSON value of a text: where it starts and ends, and its first line.
struct ValueSpan {
  size_t begin = 0;
  size_t end = 0;
  int line = 1;
};

// Splits a text into its top-level JSON values by matching brackets outside strings. A trace is
// JSON Lines, but a value spread over several lines is accepted too. Stops at the first error, or
// after `limit` values.
Result<std::vector<ValueSpan>> splitValues(const std::string& text, const std::string& name,
                                           size_t limit = SIZE_MAX) {
  std::vector<ValueSpan> spans;
  int line = 1;
  size_t i = 0;
  while (i < text.size() && spans.size() < limit) {
    const char c = text[i];
    if (c == '\n') ++line;
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
      ++i;
      continue;
    }
    if (c != '{' && c != '[') {
      return Error{fmt::format("{}:{}: expected a JSON object, found '{}'", name, line, c)};
    }
    ValueSpan span{i, i, line};
    int depth = 0;
    bool inString = false;
    for (; i < text.size(); ++i) {
      const char ch = text[i];
      if (ch == '\n') ++line;
      if (inString) {
        if (ch == '\\') {
          ++i;
        } else if (ch == '"') {
          inString = false;
        }
        continue;
      }
      if (ch == '"') {
        inString = true;
      } else if (ch == '{' || ch == '[') {
        if (++depth > kMaxNesting) {
          return Error{
              fmt::format("{}:{}: values nested deeper than {} levels", name, line, kMaxNesting)};
        }
      } else if (ch == '}' || ch == ']') {
        if (--depth == 0) {
          ++i;
          break;
        }
      }
    }
    if (depth != 0) return Error{fmt::format("{}:{}: unterminated JSON value", name, span.line)};
    span.end = i;
    spans.push_back(span);
  }
  return spans;
}

Result<Json> parseSpan(const std::string& text, const ValueSpan& span, const std::string& name) {
  Json value = Json::parse(text.begin() + static_cast<std::ptrdiff_t>(span.begin),
                           text.begin() + static_cast<std::ptrdiff_t>(span.end), nullptr, false);
  if (value.is_discarded()) return Error{fmt::format("{}:{}: invalid JSON", name, span.line)};
  return value;
}

bool isIntegerTriple(const Json& value) {
  return value.is_array() && value.size() == 3 &&
         std::all_of(value.begin(), value.end(),
                     [](const Json& x) { return x.is_number_integer(); });
}

// Escapes a JSON text for a <script> element: '<' only occurs inside JSON strings, where \u003c
// means the same; so no "</script" or "<!--" can end or confuse the element.
std::string scriptSafeJson(const std::string& json) {
  std::string out;
  out.reserve(json.size() + json.size() / 64);
  for (const char c : json) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out.push_back(c);
    }
  }
  return out;
}

std::string htmlEscaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out.push_back(c);
    }
  }
  return out;
}

bool isTraceHeader(const Json& header) {
  return header.is_object() && header.contains("format") && header["format"] == "datomsim-trace";
}

std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace

Result<std::string> readFile(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (std::filesystem::is_directory(status)) {
    return Error{fmt::format("cannot read {}: it is a directory", name)};
  }
  const bool regular = std::filesystem::is_regular_file(status);
  if (!error && !regular && !std::filesystem::is_fifo(status)) {
    return Error{fmt::format("{}: not a regular file; a device has no end to read up to", name)};
  }
  const auto tooLarge = [&] {
    return Error{
        fmt::format("{}: more than the {} MiB a file shown in the viewer may hold "
                    "(docs/limits.md)",
                    name, kMaxPageInputBytes >> 20)};
  };
  if (regular && std::filesystem::file_size(path, error) > kMaxPageInputBytes) return tooLarge();
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{fmt::format("cannot read {}: no such file or not readable", name)};
  std::string bytes;
  std::vector<char> chunk(size_t{1} << 20);
  while (in.read(chunk.data(), std::streamsize(chunk.size())) || in.gcount() > 0) {
    bytes.append(chunk.data(), size_t(in.gcount()));
    if (bytes.size() > kMaxPageInputBytes) return tooLarge();
  }
  if (in.bad()) return Error{fmt::format("cannot read {}", name)};
  return bytes;
}

Result<std::filesystem::path> executableDirectory() {
  std::error_code error;
  // The binary that holds this code: libdatomsim.so when a researcher's executable links it (its
  // prefix's share/datomsim has the bundle), else the executable itself.
  Dl_info info;
  if (dladdr(reinterpret_cast<void*>(&executableDirectory), &info) != 0 && info.dli_fname &&
      std::string_view(info.dli_fname).find(".so") != std::string_view::npos) {
    const std::filesystem::path library = std::filesystem::canonical(info.dli_fname, error);
    if (!error) return library.parent_path();
  }
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) {
    return Error{"cannot find the running executable (/proc/self/exe): " + error.message()};
  }
  return executable.parent_path();
}

std::vector<std::filesystem::path> viewerBundleCandidates(
    const std::filesystem::path& executableDirectory) {
  return {executableDirectory / kViewerBundleName,
          executableDirectory.parent_path() / "share" / "datomsim" / kViewerBundleName,
          // The shared library in a build tree (lib/ beside bin/).
          executableDirectory.parent_path() / "bin" / kViewerBundleName};
}

Result<std::string> loadViewerBundle(const std::filesystem::path& explicitPath,
                                     const std::filesystem::path& executableDirectory) {
  if (!explicitPath.empty()) return readFile(explicitPath);
  const auto candidates = viewerBundleCandidates(executableDirectory);
  for (const std::filesystem::path& candidate : candidates) {
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error)) return readFile(candidate);
  }
  return Error{fmt::format(
      "the browser viewer is not built: no {} in {} nor {}. It is built with the project when "
      "Node.js and the viewer's packages are installed: run `npm --prefix viewer ci`, then "
      "configure and build again (docs/viewer.md); or pass --viewer-js FILE",
      kViewerBundleName, candidates[0].parent_path().string(),
      candidates[1].parent_path().string())};
}

bool looksLikeTrace(const std::string& text) {
  const auto spans = splitValues(text, "", 1);
  if (!spans || spans->empty()) return false;
  const auto header = parseSpan(text, spans->front(), "");
  return header && isTraceHeader(*header);
}

Result<std::string> checkTrace(const std::string& text, const std::string& name) {
  const auto spans = splitValues(text, name);
  if (!spans) return Error{spans.error()};
  if (spans->empty()) return Error{fmt::format("{}: the trace is empty", name)};
  const auto header = parseSpan(text, spans->front(), name);
  if (!header) return Error{header.error()};
  // The viewer's own checks (export/trace_check.h), so that the page never refuses a trace
  // this command accepted.
  if (const std::string problem = headerProblem(*header); !problem.empty()) {
    return Error{fmt::format("{}:{}: {}", name, spans->front().line, problem)};
  }
  // Numbers, as JavaScript compares them: a cast to an integer would make 1e300 and 1e301 one id.
  std::set<double> ids;
  for (const Json& module : (*header)["modules"]) ids.insert(module["id"].get<double>());
  for (size_t k = 1; k < spans->size(); ++k) {
    const auto value = parseSpan(text, (*spans)[k], name);
    if (!value) return Error{value.error()};
    if (const std::string problem = changeProblem(*value, ids); !problem.empty()) {
      return Error{fmt::format("{}:{}: {}", name, (*spans)[k].line, problem)};
    }
  }
  const auto description = header->find("description");
  return description != header->end() && description->is_string() ? description->get<std::string>()
                                                                  : std::string();
}

std::string sceneTrace(const world::World& world, const std::string& description,
                       world::ModuleKind kind) {
  record::TraceWriter trace(kind);
  trace.header(world, description);
  return trace.text();
}

Result<std::string> checkOverlay(const std::string& text, const std::string& name) {
  const auto parsed = parseDocument(text, name);
  if (!parsed) return Error{parsed.error()};
  const Json& overlay = *parsed;
  if (!overlay.is_object()) return Error{fmt::format("{}: a distance map must be an object", name)};
  if (overlay.contains("distances")) {
    const Json& distances = overlay["distances"];
    if (!distances.is_array()) return Error{fmt::format("{}: \"distances\" is not a list", name)};
    for (size_t k = 0; k < distances.size(); ++k) {
      const Json& entry = distances[k];
      const bool ok = entry.is_array() && entry.size() == 4 &&
                      std::all_of(entry.begin(), entry.end(),
                                  [](const Json& x) { return x.is_number_integer(); });
      if (!ok) {
        return Error{fmt::format("{}: distances[{}] is {}, not [x,y,z,d]", name, k, entry.dump())};
      }
    }
  }
  if (overlay.contains("path")) {
    const Json& path = overlay["path"];
    if (!path.is_array()) return Error{fmt::format("{}: \"path\" is not a list", name)};
    for (size_t k = 0; k < path.size(); ++k) {
      if (!isIntegerTriple(path[k])) {
        return Error{fmt::format("{}: path[{}] is {}, not [x,y,z]", name, k, path[k].dump())};
      }
    }
  }
  if (overlay.contains("goal") && !isIntegerTriple(overlay["goal"])) {
    return Error{fmt::format("{}: \"goal\" is {}, not [x,y,z]", name, overlay["goal"].dump())};
  }
  return overlay.dump();
}

std::string overlayJson(const std::vector<std::pair<geometry::Cell, int>>& distances,
                        const std::vector<geometry::Cell>& path,
                        const std::optional<geometry::Cell>& goal) {
  std::string out = "{";
  auto sink = std::back_inserter(out);
  if (goal) fmt::format_to(sink, "\"goal\":[{},{},{}],", goal->x, goal->y, goal->z);
  out += "\"path\":[";
  for (size_t k = 0; k < path.size(); ++k) {
    fmt::format_to(sink, "{}[{},{},{}]", k ? "," : "", path[k].x, path[k].y, path[k].z);
  }
  out += "],\"distances\":[";
  for (size_t k = 0; k < distances.size(); ++k) {
    const auto& [cell, d] = distances[k];
    fmt::format_to(sink, "{}[{},{},{},{}]", k ? "," : "", cell.x, cell.y, cell.z, d);
  }
  out += "]}";
  return out;
}

Result<ViewerPage> pageForFile(const std::filesystem::path& input) {
  const auto text = readFile(input);
  if (!text) return Error{text.error()};
  ViewerPage page;
  if (looksLikeTrace(*text)) {
    const auto description = checkTrace(*text, input.string());
    if (!description) return Error{description.error()};
    page.title = description->empty() ? input.filename().string() : *description;
    page.trace = *text;
    return page;
  }
  if (!io::sceneFormatOf(input)) {
    return Error{fmt::format(
        "{}: neither a datomsim trace (its first line is no trace header) nor a scene file "
        "(.xml or .json)",
        input.string())};
  }
  const auto scene = io::readScene(input);
  if (!scene) return Error{scene.error()};
  page.title = scene->name.value_or(input.filename().string());
  page.trace = sceneTrace(scene->world, page.title, scene->moduleKind);
  return page;
}

Result<std::string> viewerHtml(const std::string& bundle, const ViewerPage& page) {
  const std::string lower = lowercase(bundle);
  for (const char* forbidden : {"</script", "<!--"}) {
    if (lower.find(forbidden) != std::string::npos) {
      return Error{fmt::format(
          "the viewer script cannot be inlined in a page: it contains \"{}\" (rebuild it with "
          "viewer/build.mjs, which escapes it)",
          forbidden)};
    }
  }
  std::string html;
  html.reserve(bundle.size() + page.trace.size() + 1024);
  html +=
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<meta name=\"generator\" content=\"datomsim view\">\n<title>";
  html += htmlEscaped(page.title.empty() ? "datomsim" : "datomsim: " + page.title);
  html += "</title>\n</head>\n<body>\n<div id=\"datomsim-viewer\"></div>\n";
  html += "<script type=\"application/x-ndjson\" id=\"datomsim-trace\">\n";
  html += scriptSafeJson(page.trace);
  html += "</script>\n";
  if (page.overlay) {
    html += "<script type=\"application/json\" id=\"datomsim-overlay\">";
    html += scriptSafeJson(*page.overlay);
    html += "</script>\n";
  }
  if (page.loads) {
    html += "<script type=\"application/json\" id=\"datomsim-loads\">";
    html += scriptSafeJson(*page.loads);
    html += "</script>\n";
  }
  html += "<script>\n";
  html += bundle;
  html += "\n</script>\n</body>\n</html>\n";
  return html;
}

Status writeViewerPage(const std::filesystem::path& path, const std::string& bundle,
                       const ViewerPage& page) {
  const auto html = viewerHtml(bundle, page);
  if (!html) return Error{html.error()};
  return writeFileAtomically(path, *html);
}

}  // namespace datomsim::exporting
