#include "studio/server.h"

#include <fmt/format.h>

#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <chrono>
#include <csignal>
#include <deque>
#include <random>
#include <string_view>
#include <utility>

namespace datomsim::studio {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

struct Server::State {
  State(Session& session, ServerOptions options) : session(session), options(std::move(options)) {}
  Session& session;
  ServerOptions options;
  asio::io_context io{1};
  tcp::acceptor acceptor{io};
  asio::signal_set signals{io, SIGINT, SIGTERM};
};

namespace {

// The largest request a page sends: a scene file being opened is the largest.
constexpr size_t kMaxRequestBytes = size_t{64} << 20;

std::string_view pathOf(std::string_view target) {
  return target.substr(0, target.find('?'));
}

// Whether the target's query carries the token, when the studio asks for one.
bool authorised(std::string_view target, const std::string& token) {
  if (token.empty()) return true;
  const size_t query = target.find('?');
  if (query == std::string_view::npos) return false;
  std::string_view rest = target.substr(query + 1);
  while (!rest.empty()) {
    const size_t end = rest.find('&');
    if (rest.substr(0, end) == "token=" + token) return true;
    if (end == std::string_view::npos) break;
    rest.remove_prefix(end + 1);
  }
  return false;
}

// A page's socket: each text message a request to the session, answered in order.
class Socket : public std::enable_shared_from_this<Socket> {
 public:
  Socket(tcp::socket&& socket, Session& session) : ws_(std::move(socket)), session_(session) {}

  void start(http::request<http::string_body> request) {
    ws_.set_option(websocket::stream_base::timeout::suggested(beast::role_type::server));
    ws_.read_message_max(kMaxRequestBytes);
    ws_.async_accept(request, [self = shared_from_this()](beast::error_code error) {
      if (!error) self->read();
    });
  }

 private:
  void read() {
    ws_.async_read(buffer_, [self = shared_from_this()](beast::error_code error, size_t) {
      // Closed, or gone (a page reloaded): the session stays as it is for the next page.
      if (error) return;
      std::string request = beast::buffers_to_string(self->buffer_.data());
      self->buffer_.consume(self->buffer_.size());
      self->send(self->ws_.got_text()
                     ? self->session_.handle(request)
                     : std::string(R"({"ok":false,"error":"a request is text, not binary"})"));
      self->read();
    });
  }

  void send(std::string text) {
    outbox_.push_back(std::move(text));
    if (outbox_.size() == 1) write();
  }

  void write() {
    ws_.text(true);
    ws_.async_write(asio::buffer(outbox_.front()),
                    [self = shared_from_this()](beast::error_code error, size_t) {
                      if (error) return;
                      self->outbox_.pop_front();
                      if (!self->outbox_.empty()) self->write();
                    });
  }

  websocket::stream<beast::tcp_stream> ws_;
  Session& session_;
  beast::flat_buffer buffer_;
  std::deque<std::string> outbox_;
};

// One HTTP connection: the page, or the upgrade to the page's socket.
class Connection : public std::enable_shared_from_this<Connection> {
 public:
  Connection(tcp::socket&& socket, Server::State& state)
      : stream_(std::move(socket)), state_(state) {}

  void read() {
    parser_.emplace();
    parser_->body_limit(kMaxRequestBytes);
    stream_.expires_after(std::chrono::seconds(30));
    http::async_read(stream_, buffer_, *parser_,
                     [self = shared_from_this()](beast::error_code error, size_t) {
                       if (error) return self->close();
                       self->answer(self->parser_->release());
                     });
  }

 private:
  void answer(http::request<http::string_body> request) {
    const std::string_view target(request.target().data(), request.target().size());
    const bool allowed = authorised(target, state_.options.token);
    if (websocket::is_upgrade(request) && allowed && pathOf(target) == "/ws") {
      stream_.expires_never();
      std::make_shared<Socket>(stream_.release_socket(), state_.session)->start(std::move(request));
      return;
    }
    auto response = std::make_shared<http::response<http::string_body>>();
    response->version(request.version());
    response->set(http::field::server, "datomsim studio");
    response->set(http::field::cache_control, "no-store");
    response->set(http::field::content_type, "text/plain; charset=utf-8");
    if (!allowed) {
      response->result(http::status::forbidden);
      response->body() =
          "This studio asks for its access token: open the address it printed when it started.\n";
    } else if (request.method() != http::verb::get && request.method() != http::verb::head) {
      response->result(http::status::method_not_allowed);
      response->body() = "Only GET is served here; the studio's requests go over its socket.\n";
    } else if (pathOf(target) == "/favicon.ico") {
      // No icon: said without an error in the page's console.
      response->result(http::status::no_content);
    } else if (pathOf(target) == "/") {
      response->result(http::status::ok);
      response->set(http::field::content_type, "text/html; charset=utf-8");
      response->body() = state_.options.page;
    } else {
      response->result(http::status::not_found);
      response->body() = fmt::format("Nothing at {}: the studio is at /.\n", pathOf(target));
    }
    response->keep_alive(request.keep_alive());
    response->prepare_payload();
    if (request.method() == http::verb::head) response->body().clear();
    http::async_write(stream_, *response,
                      [self = shared_from_this(), response](beast::error_code error, size_t) {
                        if (error || response->need_eof()) return self->close();
                        self->read();
                      });
  }

  void close() {
    beast::error_code ignored;
    stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
  }

  beast::tcp_stream stream_;
  Server::State& state_;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
};

void acceptNext(Server::State& state) {
  state.acceptor.async_accept([&state](beast::error_code error, tcp::socket socket) {
    if (!error) std::make_shared<Connection>(std::move(socket), state)->read();
    if (state.acceptor.is_open()) acceptNext(state);
  });
}

}  // namespace

Result<std::unique_ptr<Server>> Server::listen(Session& session, ServerOptions options) {
  auto state = std::make_unique<State>(session, std::move(options));
  beast::error_code error;
  const auto address = asio::ip::make_address(state->options.host, error);
  if (error) {
    return Error{
        fmt::format("--host {}: not an IP address ({})", state->options.host, error.message())};
  }
  const tcp::endpoint endpoint(address, state->options.port);
  const std::string where = fmt::format("{}:{}", state->options.host, state->options.port);
  state->acceptor.open(endpoint.protocol(), error);
  if (!error) state->acceptor.set_option(asio::socket_base::reuse_address(true), error);
  if (!error) state->acceptor.bind(endpoint, error);
  if (!error) state->acceptor.listen(asio::socket_base::max_listen_connections, error);
  if (error) return Error{fmt::format("cannot listen on {}: {}", where, error.message())};
  return std::unique_ptr<Server>(new Server(std::move(state)));
}

Server::Server(std::unique_ptr<State> state) : state_(std::move(state)) {}

Server::~Server() = default;

uint16_t Server::port() const {
  return state_->acceptor.local_endpoint().port();
}

void Server::run() {
  state_->signals.async_wait([this](beast::error_code, int) { stop(); });
  acceptNext(*state_);
  state_->io.run();
}

void Server::stop() {
  asio::post(state_->io, [this] {
    beast::error_code ignored;
    state_->acceptor.close(ignored);
    state_->io.stop();
  });
}

std::string newToken() {
  std::random_device source;
  std::string token;
  for (int k = 0; k < 4; ++k) token += fmt::format("{:08x}", uint32_t(source()));
  return token;
}

}  // namespace datomsim::studio
