#include "video/devtools.h"

#include <poll.h>
#include <unistd.h>

#include <fmt/format.h>
#include <array>
#include <cerrno>
#include <cstring>

namespace datomsim::video {

using Json = nlohmann::json;

DevTools::DevTools(int commandsFd, int repliesFd, std::chrono::milliseconds timeout)
    : commands_(commandsFd), replies_(repliesFd), timeout_(timeout) {}

Result<Json> DevTools::nextMessage() {
  const auto deadline = std::chrono::steady_clock::now() + timeout_;
  while (true) {
    if (const size_t end = buffer_.find('\0'); end != std::string::npos) {
      Json message =
          Json::parse(buffer_.begin(), buffer_.begin() + std::ptrdiff_t(end), nullptr, false);
      buffer_.erase(0, end + 1);
      if (message.is_discarded()) return Error{"the browser sent a message that is not JSON"};
      return message;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      return Error{
          fmt::format("the browser did not answer within {} s", double(timeout_.count()) / 1000)};
    }
    pollfd ready{replies_, POLLIN, 0};
    const int polled = ::poll(&ready, 1, int(left.count()));
    if (polled < 0 && errno == EINTR) continue;
    if (polled < 0) return Error{fmt::format("poll: {}", std::strerror(errno))};
    if (polled == 0) continue;
    std::array<char, 1 << 16> chunk;
    const ssize_t read = ::read(replies_, chunk.data(), chunk.size());
    if (read < 0 && errno == EINTR) continue;
    if (read <= 0) return Error{"the browser closed its connection (it stopped or crashed)"};
    buffer_.append(chunk.data(), size_t(read));
  }
}

Result<Json> DevTools::call(const std::string& method, const Json& params,
                            const std::string& session) {
  const int id = nextId_++;
  Json command = {{"id", id}, {"method", method}, {"params", params}};
  if (!session.empty()) command["sessionId"] = session;
  std::string bytes = command.dump();
  bytes.push_back('\0');
  std::string_view left = bytes;
  while (!left.empty()) {
    const ssize_t written = ::write(commands_, left.data(), left.size());
    if (written < 0 && errno == EINTR) continue;
    if (written < 0)
      return Error{fmt::format("{}: the browser is gone ({})", method, std::strerror(errno))};
    left.remove_prefix(size_t(written));
  }
  while (true) {
    Result<Json> message = nextMessage();
    if (!message) return Error{fmt::format("{}: {}", method, message.error())};
    const Json& reply = *message;
    if (!reply.contains("id") || reply["id"] != id) continue;  // an event, or an older reply
    if (reply.contains("error")) {
      return Error{fmt::format("{}: {}", method, reply["error"].value("message", "failed"))};
    }
    return reply.value("result", Json::object());
  }
}

Result<Json> DevTools::evaluate(const std::string& expression, const std::string& session) {
  Result<Json> result =
      call("Runtime.evaluate",
           {{"expression", expression}, {"returnByValue", true}, {"awaitPromise", true}}, session);
  if (!result) return result;
  if (result->contains("exceptionDetails")) {
    const Json& details = (*result)["exceptionDetails"];
    std::string text = details.value("text", "exception");
    if (details.contains("exception") && details["exception"].contains("description")) {
      text = details["exception"]["description"].get<std::string>();
    }
    return Error{fmt::format("the page failed on {}: {}", expression, text)};
  }
  return result->contains("result") ? (*result)["result"].value("value", Json()) : Json();
}

Result<std::string> decodeBase64(const std::string& text) {
  static constexpr auto kValues = [] {
    std::array<int8_t, 256> values{};
    values.fill(-1);
    const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int k = 0; k < 64; ++k) values[uint8_t(alphabet[k])] = int8_t(k);
    return values;
  }();
  std::string bytes;
  bytes.reserve(text.size() / 4 * 3);
  uint32_t bits = 0;
  int count = 0;
  for (size_t k = 0; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '=') break;
    const int value = kValues[uint8_t(c)];
    if (value < 0) return Error{fmt::format("base64: character {} at {} is not base64", c, k)};
    bits = (bits << 6) | uint32_t(value);
    count += 6;
    if (count >= 8) {
      count -= 8;
      bytes.push_back(char((bits >> count) & 0xff));
    }
  }
  return bytes;
}

}  // namespace datomsim::video
