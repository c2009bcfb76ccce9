// Listener, plain HTTP (health, metrics, WebSocket upgrade), threads, signals and shutdown.
#include "carrom/server/server.hpp"

#include "net_common.hpp"
#include "net_session.hpp"

#include <boost/asio/signal_set.hpp>
#include <boost/beast/websocket/rfc6455.hpp>
#include <spdlog/spdlog.h>

#include <stdexcept>
#include <thread>
#include <vector>

namespace carrom::server::net {

namespace {

// Reads one HTTP request; answers GET /healthz and GET /metrics, hands a WebSocket upgrade to a
// WsSession, and answers anything else with 404 (or 405).
class HttpSession : public std::enable_shared_from_this<HttpSession> {
public:
    HttpSession(Core& core, tcp::socket socket) : core_(core), stream_(std::move(socket)) {}

    void run() {
        parser_.emplace();
        parser_->header_limit(8192);
        parser_->body_limit(1024);
        stream_.expires_after(to_duration(core_.settings.handshake_timeout_s));
        http::async_read(stream_, buffer_, *parser_,
                         beast::bind_front_handler(&HttpSession::on_read, shared_from_this()));
    }

private:
    void on_read(beast::error_code ec, std::size_t) {
        if (ec) {
            return; // timeout, garbage or a closed connection
        }
        auto request = parser_->release();
        if (beast::websocket::is_upgrade(request)) {
            start_ws_session(core_, std::move(stream_), std::move(request));
            return;
        }
        core_.metrics.http_requests_total.fetch_add(1, std::memory_order_relaxed);
        respond(request);
    }

    void respond(const http::request<http::string_body>& request) {
        auto response = std::make_shared<http::response<http::string_body>>();
        response->version(request.version());
        response->set(http::field::server, "carrom-server");
        response->keep_alive(false);
        const auto target = request.target();
        const bool get = request.method() == http::verb::get;
        if (target == "/healthz" || target == "/metrics") {
            if (!get) {
                response->result(http::status::method_not_allowed);
                response->set(http::field::allow, "GET");
                response->body() = "method not allowed\n";
            } else if (target == "/healthz") {
                response->result(core_.stopping ? http::status::service_unavailable
                                                : http::status::ok);
                response->body() = core_.stopping ? "stopping\n" : "ok\n";
            } else {
                response->result(http::status::ok);
                response->set(http::field::content_type, "text/plain; version=0.0.4");
                response->body() = core_.metrics.prometheus_text();
            }
        } else {
            response->result(http::status::not_found);
            response->body() = "not found\n";
        }
        if (!response->has_content_length() && response->body().size() > 0 &&
            response->find(http::field::content_type) == response->end()) {
            response->set(http::field::content_type, "text/plain");
        }
        response->prepare_payload();
        http::async_write(stream_, *response,
                          [self = shared_from_this(), response](beast::error_code, std::size_t) {
                              beast::error_code ignored;
                              self->stream_.socket().shutdown(tcp::socket::shutdown_send, ignored);
                          });
    }

    Core& core_;
    beast::tcp_stream stream_;
    beast::flat_buffer buffer_;
    std::optional<http::request_parser<http::string_body>> parser_;
};

class Listener : public std::enable_shared_from_this<Listener> {
public:
    Listener(Core& core, tcp::endpoint endpoint)
        : core_(core), acceptor_(asio::make_strand(core.ioc)) {
        acceptor_.open(endpoint.protocol());
        acceptor_.set_option(asio::socket_base::reuse_address(true));
        acceptor_.bind(endpoint);
        acceptor_.listen(asio::socket_base::max_listen_connections);
    }

    std::uint16_t port() const { return acceptor_.local_endpoint().port(); }

    void run() { do_accept(); }

    void stop() {
        asio::post(acceptor_.get_executor(), [self = shared_from_this()] {
            beast::error_code ignored;
            self->acceptor_.close(ignored);
        });
    }

private:
    void do_accept() {
        acceptor_.async_accept(asio::make_strand(core_.ioc),
                               beast::bind_front_handler(&Listener::on_accept, shared_from_this()));
    }

    void on_accept(beast::error_code ec, tcp::socket socket) {
        if (ec == asio::error::operation_aborted || !acceptor_.is_open()) {
            return;
        }
        if (!ec) {
            // Snapshots are small and time-critical: send each at once, without Nagle's delay.
            beast::error_code ignored;
            socket.set_option(tcp::no_delay(true), ignored);
            std::make_shared<HttpSession>(core_, std::move(socket))->run();
        }
        do_accept();
    }

    Core& core_;
    tcp::acceptor acceptor_;
};

} // namespace

} // namespace carrom::server::net

namespace carrom::server {

struct Server::Impl {
    Impl(ServerSettings settings, BotFactory bots) : core(std::move(settings), std::move(bots)) {}

    net::Core core;
    std::shared_ptr<net::Listener> listener;
    std::vector<std::thread> threads;
    std::optional<net::asio::executor_work_guard<net::asio::io_context::executor_type>> work;
    bool stopped = false;
};

Server::Server(ServerSettings settings, BotFactory bots)
    : impl_(std::make_unique<Impl>(std::move(settings), std::move(bots))) {}

Server::~Server() {
    shutdown();
}

std::uint16_t Server::listen() {
    auto& core = impl_->core;
    try {
        const auto address = net::asio::ip::make_address(core.settings.host);
        impl_->listener =
            std::make_shared<net::Listener>(core, net::tcp::endpoint(address, core.settings.port));
    } catch (const std::exception& e) {
        throw std::runtime_error("cannot listen on " + core.settings.host + ":" +
                                 std::to_string(core.settings.port) + ": " + e.what());
    }
    impl_->listener->run();
    return impl_->listener->port();
}

void Server::start() {
    impl_->work.emplace(impl_->core.ioc.get_executor());
    const int count = std::max(1, impl_->core.settings.threads);
    for (int i = 0; i < count; ++i) {
        impl_->threads.emplace_back([this] { impl_->core.ioc.run(); });
    }
}

void Server::shutdown() {
    if (impl_->stopped) {
        return;
    }
    impl_->stopped = true;
    auto& core = impl_->core;
    core.stopping = true;
    if (impl_->listener) {
        impl_->listener->stop();
    }
    std::vector<std::shared_ptr<net::WsSession>> sessions;
    {
        std::lock_guard lock(core.sessions_mutex);
        for (auto& [ptr, weak] : core.sessions) {
            if (auto s = weak.lock()) {
                sessions.push_back(std::move(s));
            }
        }
    }
    for (auto& s : sessions) {
        s->shutdown();
    }
    sessions.clear();
    const auto deadline =
        std::chrono::steady_clock::now() + net::to_duration(core.settings.shutdown_grace_s);
    while (!impl_->threads.empty() && core.metrics.connections.load() > 0 &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    core.registry.for_each_room([](const std::shared_ptr<net::RoomActor>& room) { room->stop(); });
    impl_->work.reset();
    core.ioc.stop();
    for (auto& t : impl_->threads) {
        t.join();
    }
    impl_->threads.clear();
    core.bot_pool.join();
}

void Server::run_until_signal() {
    net::asio::io_context signal_ioc;
    net::asio::signal_set signals(signal_ioc, SIGINT, SIGTERM);
    signals.async_wait([](const boost::system::error_code&, int signal) {
        spdlog::info("signal {}: shutting down", signal);
    });
    signal_ioc.run();
    shutdown();
}

const Metrics& Server::metrics() const {
    return impl_->core.metrics;
}
const ServerSettings& Server::settings() const {
    return impl_->core.settings;
}

} // namespace carrom::server
