// The Chrome DevTools protocol over a pair of pipes (Chromium's --remote-debugging-pipe): each
// message one JSON object ended by a NUL byte; a command carries an id, its reply the same id;
// events (messages with a "method" and no id) are skipped.
#pragma once

#include <chrono>
#include <nlohmann/json.hpp>
#include <string>

#include "datomsim/result.h"

namespace datomsim::video {

class DevTools {
 public:
  // `commandsFd` is written, `repliesFd` read; neither is owned. A command whose reply takes
  // longer than `timeout` fails: a browser that stopped answering ends the recording, it does not
  // hang it.
  DevTools(int commandsFd, int repliesFd, std::chrono::milliseconds timeout);

  // Sends `method` with `params` (to the page of `session` when not empty) and returns the
  // reply's "result", or an error with the protocol's message.
  Result<nlohmann::json> call(const std::string& method,
                              const nlohmann::json& params = nlohmann::json::object(),
                              const std::string& session = "");

  // Evaluates a JavaScript expression in the page and returns its value (promises awaited); a
  // thrown exception is an error with its text.
  Result<nlohmann::json> evaluate(const std::string& expression, const std::string& session);

 private:
  Result<nlohmann::json> nextMessage();

  int commands_;
  int replies_;
  std::chrono::milliseconds timeout_;
  int nextId_ = 1;
  std::string buffer_;
};

// The bytes a base64 text stands for (the protocol's screenshots); an error at a character
// outside the alphabet.
Result<std::string> decodeBase64(const std::string& text);

}  // namespace datomsim::video
