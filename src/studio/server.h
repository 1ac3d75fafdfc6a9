// The studio's local server (docs/studio.md): the page over HTTP, and the session's protocol over
// a WebSocket, on one port, with Boost.Beast on one thread.
//
// It listens on 127.0.0.1 unless told another address; then every request must carry the access
// token (`?token=...` in the page's address and the socket's), printed when the server starts, so
// that nobody else on the network drives the studio. Requests are answered one at a time, in the
// order they come, by the one session: every page sees the same state.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "studio/session.h"

namespace datomsim::studio {

struct ServerOptions {
  std::string host = "127.0.0.1";
  uint16_t port = 0;  // 0: any free port
  // Required of every request when not empty.
  std::string token;
  // What GET / answers: the studio's page.
  std::string page;
};

class Server {
 public:
  // Listens at once; a port taken or an address that cannot be had is refused naming it.
  static Result<std::unique_ptr<Server>> listen(Session& session, ServerOptions options);
  ~Server();

  // The port listened on (the one given, or the free one chosen).
  uint16_t port() const;
  // Serves until stop() or SIGINT/SIGTERM.
  void run();
  // From another thread: ends run() after the request in progress.
  void stop();

  // The server's insides (server.cpp): its connections hold it.
  struct State;

 private:
  explicit Server(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

// A new access token: 32 hexadecimal digits from the system's random source.
std::string newToken();

}  // namespace datomsim::studio
