// The studio's server as a page meets it: the page over HTTP, the protocol over a WebSocket, the
// session's state kept when a page goes and another comes, and the access token asked of every
// request when the studio is told to ask for one.
#include "studio/server.h"

#include <gtest/gtest.h>

#include <boost/asio.hpp>
#include <boost/beast.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "io/scene_file.h"

namespace datomsim::studio {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using nlohmann::json;

// A studio served on a free port of 127.0.0.1 by a thread of its own, stopped at the end.
class Served {
 public:
  explicit Served(std::string token = "")
      : session_(*io::readScene(std::string(DATOMSIM_SOURCE_DIR) + "/scenes/paper-arch-hole1.json"),
                 "arch") {
    ServerOptions options;
    options.page = "<!doctype html><title>the page</title>";
    options.token = std::move(token);
    auto server = Server::listen(session_, options);
    EXPECT_TRUE(server.ok()) << server.error();
    server_ = std::move(*server);
    thread_ = std::thread([this] { server_->run(); });
  }
  ~Served() {
    server_->stop();
    thread_.join();
  }
  uint16_t port() const { return server_->port(); }
  const Session& session() const { return session_; }

 private:
  Session session_;
  std::unique_ptr<Server> server_;
  std::thread thread_;
};

http::response<http::string_body> get(uint16_t port, const std::string& target) {
  asio::io_context io;
  beast::tcp_stream stream(io);
  stream.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  http::request<http::empty_body> request(http::verb::get, target, 11);
  request.set(http::field::host, "127.0.0.1");
  http::write(stream, request);
  beast::flat_buffer buffer;
  http::response<http::string_body> response;
  http::read(stream, buffer, response);
  return response;
}

// A page's socket: one request, its reply.
class Page {
 public:
  explicit Page(uint16_t port, const std::string& target = "/ws") : ws_(io_) {
    asio::connect(ws_.next_layer(),
                  std::array{tcp::endpoint(asio::ip::make_address("127.0.0.1"), port)});
    ws_.handshake("127.0.0.1", target);
  }
  json ask(const std::string& request) {
    ws_.write(asio::buffer(request));
    beast::flat_buffer buffer;
    ws_.read(buffer);
    return json::parse(beast::buffers_to_string(buffer.data()));
  }
  void close() { ws_.close(websocket::close_code::normal); }

 private:
  asio::io_context io_;
  websocket::stream<tcp::socket> ws_;
};

TEST(StudioServer, ServesThePageAndAnswersOverItsSocket) {
  Served studio;
  const auto page = get(studio.port(), "/");
  EXPECT_EQ(page.result(), http::status::ok);
  EXPECT_EQ(page.body(), "<!doctype html><title>the page</title>");
  EXPECT_EQ(get(studio.port(), "/elsewhere").result(), http::status::not_found);

  Page first(studio.port());
  const json scene = first.ask(R"({"op":"scene"})");
  EXPECT_TRUE(scene.at("ok").get<bool>());
  EXPECT_EQ(scene.at("scene").at("modules").size(), 131u);
  // A hostile or broken message: an error reply, and the socket still answers.
  const json broken = first.ask("{\"op\": \"add\", \"cell\": [1e400");
  EXPECT_FALSE(broken.at("ok").get<bool>());
  const json added = first.ask(R"({"op":"add","cell":"0,0,1"})");
  EXPECT_TRUE(added.at("ok").get<bool>()) << added;
  first.close();

  // The page reloaded: a new socket finds the studio as the last one left it.
  Page second(studio.port());
  EXPECT_EQ(second.ask(R"({"op":"scene"})").at("scene").at("modules").size(), 132u);
}

TEST(StudioServer, AskedForATokenItRefusesEveryRequestWithout) {
  Served studio("abc123");
  EXPECT_EQ(get(studio.port(), "/").result(), http::status::forbidden);
  EXPECT_EQ(get(studio.port(), "/?token=wrong").result(), http::status::forbidden);
  EXPECT_EQ(get(studio.port(), "/?token=abc123").result(), http::status::ok);
  EXPECT_THROW(Page(studio.port(), "/ws"), beast::system_error);
  Page allowed(studio.port(), "/ws?token=abc123");
  EXPECT_TRUE(allowed.ask(R"({"op":"scene"})").at("ok").get<bool>());
}

TEST(StudioServer, APortTakenIsRefusedNamingIt) {
  Served studio;
  Session other(*io::readScene(std::string(DATOMSIM_SOURCE_DIR) + "/scenes/paper-arch-hole1.json"),
                "arch");
  ServerOptions options;
  options.port = studio.port();
  const auto refused = Server::listen(other, options);
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().find("cannot listen on 127.0.0.1:" + std::to_string(studio.port())),
            std::string::npos)
      << refused.error();
  options.port = 0;
  options.host = "not-an-address";
  const auto bad = Server::listen(other, options);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.error().find("--host not-an-address"), std::string::npos) << bad.error();
}

}  // namespace
}  // namespace datomsim::studio
