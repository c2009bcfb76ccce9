// Connection over Boost.Beast: one io_context run by the connection's own I/O thread. A wss://
// URL adds the TLS handshake (carrom/tls/client_tls.hpp: the certificate verified for the URL's
// host) between the TCP connect and the WebSocket handshake, within the connect timeout. Every
// socket operation happens on that thread; the public functions only post work to it or read
// the shared inbox and status under a mutex.
//
// Sends made while Connecting wait in the outbox and go out once the handshake is done (so a
// caller may send hello right after open()); sends after Closed are dropped.
//
// Invariants: at most one async_read and one async_write (or async_close) in flight; the
// outbox holds at most options.max_queued_sends texts; once the status is Closed it stays so.
#include "carrom/net/connection.hpp"
#include "carrom/net/ws_url.hpp"
#include "carrom/proto/codec.hpp"
#include "ws_error_text.hpp"

#include "carrom/tls/client_tls.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/core/tcp_stream.hpp>
#include <boost/beast/websocket/stream.hpp>

#include <condition_variable>
#include <deque>
#include <mutex>
#include <thread>

namespace carrom::net {

namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

// How long a polite close may take before the socket is simply dropped.
constexpr std::chrono::milliseconds kCloseTimeout{2000};

class WsConnection final : public Connection {
public:
    // tls_context: for a wss:// url (null for ws://).
    WsConnection(WsUrl url, const ConnectionOptions& options,
                 std::shared_ptr<asio::ssl::context> tls_context)
        : url_(std::move(url)), options_(options), tls_context_(std::move(tls_context)),
          resolver_(ioc_), deadline_(ioc_), ws_(ioc_) {
        asio::post(ioc_, [this] { start(); });
        thread_ = std::thread([this] { ioc_.run(); });
    }

    ~WsConnection() override {
        close();
        ioc_.stop();
        if (thread_.joinable()) {
            thread_.join();
        }
    }
    WsConnection(const WsConnection&) = delete;
    WsConnection& operator=(const WsConnection&) = delete;

    void send(const proto::ClientMessage& message) override { send_text(proto::encode(message)); }

    void send_text(const std::string& text) override {
        if (status().state == ConnectionState::Closed) {
            return;
        }
        asio::post(ioc_, [this, text] { enqueue(text); });
    }

    std::vector<proto::ServerMessage> poll() override {
        std::lock_guard lock(mutex_);
        std::vector<proto::ServerMessage> out;
        out.swap(inbox_);
        return out;
    }

    bool wait(std::chrono::milliseconds timeout) override {
        std::unique_lock lock(mutex_);
        const auto version = state_version_;
        cv_.wait_for(lock, timeout, [&] { return !inbox_.empty() || state_version_ != version; });
        return !inbox_.empty();
    }

    ConnectionStatus status() const override {
        std::lock_guard lock(mutex_);
        return status_;
    }

    int decode_errors() const override {
        std::lock_guard lock(mutex_);
        return decode_errors_;
    }

    void close() override {
        {
            std::lock_guard lock(mutex_);
            if (status_.state == ConnectionState::Closed) {
                return;
            }
        }
        asio::post(ioc_, [this] { begin_close(); });
        std::unique_lock lock(mutex_);
        const bool closed = cv_.wait_for(lock, kCloseTimeout + std::chrono::milliseconds(500),
                                         [&] { return status_.state == ConnectionState::Closed; });
        if (!closed) { // the I/O thread is stuck: give up on politeness
            lock.unlock();
            ioc_.stop();
            set_closed("Closed by this client.");
        }
    }

private:
    // --- status (any thread) ---
    void set_state(ConnectionState state, std::string detail) {
        {
            std::lock_guard lock(mutex_);
            if (status_.state == ConnectionState::Closed) {
                return;
            }
            status_.state = state;
            status_.detail = std::move(detail);
            ++state_version_;
        }
        cv_.notify_all();
    }
    void set_closed(std::string detail) { set_state(ConnectionState::Closed, std::move(detail)); }
    bool is_closed() const { return status().state == ConnectionState::Closed; }

    // --- connecting (I/O thread) ---
    void start() {
        deadline_.expires_after(options_.connect_timeout);
        deadline_.async_wait([this](beast::error_code ec) {
            if (!ec && !open_) {
                fail(connect_timeout_text(url_, options_.connect_timeout));
            }
        });
        resolver_.async_resolve(url_.host, std::to_string(url_.port),
                                [this](beast::error_code ec, tcp::resolver::results_type results) {
                                    on_resolve(ec, std::move(results));
                                });
    }

    void on_resolve(beast::error_code ec, const tcp::resolver::results_type& results) {
        if (is_closed()) {
            return;
        }
        if (ec) {
            fail(resolve_error_text(url_, ec));
            return;
        }
        beast::get_lowest_layer(ws_).async_connect(
            results, [this](beast::error_code e, const tcp::endpoint&) { on_connect(e); });
    }

    void on_connect(beast::error_code ec) {
        if (is_closed()) {
            return;
        }
        if (ec) {
            fail(connect_error_text(url_, ec));
            return;
        }
        beast::error_code ignored;
        beast::get_lowest_layer(ws_).socket().set_option(tcp::no_delay(true), ignored);
        if (url_.tls) {
            if (!tls::start_client_tls(ws_.next_layer(), tls_context_, url_.host,
                                       verify_failure_)) {
                fail("The host name '" + url_.host + "' cannot be checked against a certificate.");
                return;
            }
            ws_.next_layer().tls().async_handshake(
                asio::ssl::stream_base::client,
                [this](beast::error_code e) { on_tls_handshake(e); });
            return;
        }
        websocket_handshake();
    }

    void on_tls_handshake(beast::error_code ec) {
        if (is_closed()) {
            return;
        }
        if (ec) {
            fail(tls::tls_handshake_error_text(url_.authority(), ec, verify_failure_));
            return;
        }
        websocket_handshake();
    }

    void websocket_handshake() {
        ws_.read_message_max(proto::kMaxServerMessageBytes);
        ws_.set_option(websocket::stream_base::decorator([](websocket::request_type& request) {
            request.set(beast::http::field::user_agent, "carrom-net");
        }));
        ws_.async_handshake(url_.authority(), url_.target,
                            [this](beast::error_code e) { on_handshake(e); });
    }

    void on_handshake(beast::error_code ec) {
        if (is_closed()) {
            return;
        }
        if (ec) {
            fail(handshake_error_text(url_, ec));
            return;
        }
        deadline_.cancel();
        websocket::stream_base::timeout timeouts{};
        timeouts.handshake_timeout = kCloseTimeout; // bounds the closing handshake
        if (options_.silence_timeout.count() > 0) {
            timeouts.idle_timeout = options_.silence_timeout;
            timeouts.keep_alive_pings = true; // a ping at half of it; the server's pong resets it
        } else {
            timeouts.idle_timeout = websocket::stream_base::none();
            timeouts.keep_alive_pings = false;
        }
        ws_.set_option(timeouts);
        ws_.text(true);
        open_ = true;
        set_state(ConnectionState::Open, "Connected to " + url_.authority() + ".");
        read();
        write_next(); // what was queued while connecting
    }

    // Ends a connection that never opened (or broke) with the given sentence.
    void fail(std::string detail) {
        set_closed(std::move(detail));
        deadline_.cancel();
        resolver_.cancel();
        beast::get_lowest_layer(ws_).close();
        outbox_.clear();
    }

    // --- reading (I/O thread) ---
    void read() {
        ws_.async_read(buffer_, [this](beast::error_code ec, std::size_t) { on_read(ec); });
    }

    void on_read(beast::error_code ec) {
        if (ec) {
            const bool ours = closing_;
            const auto reason = ws_.reason();
            if (!ours && ec == websocket::error::closed) {
                std::lock_guard lock(mutex_);
                status_.close_code = reason.code;
            }
            if (ours) {
                fail("Closed by this client.");
            } else if (ec == beast::error::timeout) {
                fail(silence_text(url_, options_.silence_timeout));
            } else {
                fail(read_error_text(url_, ec, reason.code,
                                     std::string(reason.reason.data(), reason.reason.size())));
            }
            return;
        }
        const bool text = ws_.got_text();
        const auto data = buffer_.cdata();
        const std::string_view frame(static_cast<const char*>(data.data()), data.size());
        auto decoded =
            text ? proto::decode_server(frame) : proto::DecodedMessage<proto::ServerMessage>{};
        buffer_.consume(buffer_.size());
        {
            std::lock_guard lock(mutex_);
            if (decoded.ok()) {
                inbox_.push_back(std::move(*decoded.message));
            } else {
                ++decode_errors_;
            }
        }
        cv_.notify_all();
        read();
    }

    // --- writing (I/O thread) ---
    void enqueue(std::string text) {
        if (is_closed() || closing_ || outbox_.size() >= options_.max_queued_sends) {
            return; // closed, closing, or the socket is too slow: dropped
        }
        outbox_.push_back(std::move(text));
        if (open_ && !writing_) {
            write_next();
        }
    }

    void write_next() {
        if (!open_ || writing_ || is_closed()) {
            return;
        }
        if (outbox_.empty()) {
            if (closing_ && !close_sent_) {
                close_sent_ = true;
                writing_ = true;
                ws_.async_close(websocket::close_code::normal, [this](beast::error_code) {
                    writing_ = false; // the read loop sees the end and sets the status
                });
            }
            return;
        }
        writing_ = true;
        ws_.async_write(asio::buffer(outbox_.front()), [this](beast::error_code ec, std::size_t) {
            writing_ = false;
            if (ec) {
                return; // the read loop reports the broken connection
            }
            outbox_.pop_front();
            write_next();
        });
    }

    void begin_close() {
        if (is_closed()) {
            return;
        }
        closing_ = true;
        if (!open_) {
            fail("Closed by this client.");
            return;
        }
        write_next(); // flushes the outbox, then sends the close frame
    }

    WsUrl url_;
    ConnectionOptions options_;
    std::shared_ptr<asio::ssl::context> tls_context_;
    asio::io_context ioc_{1};
    tcp::resolver resolver_;
    asio::steady_timer deadline_; // connect timeout (TCP, TLS and WebSocket handshakes)
    websocket::stream<tls::FlexStream<beast::tcp_stream>> ws_;
    tls::VerifyFailure verify_failure_; // the certificate refused in the TLS handshake
    beast::flat_buffer buffer_;
    // I/O thread only.
    std::deque<std::string> outbox_;
    bool open_ = false;
    bool writing_ = false;
    bool closing_ = false;
    bool close_sent_ = false;
    // Shared, under mutex_.
    mutable std::mutex mutex_;
    std::condition_variable cv_;
    std::vector<proto::ServerMessage> inbox_;
    ConnectionStatus status_;
    int decode_errors_ = 0;
    std::uint64_t state_version_ = 0;
    std::thread thread_;
};

// A connection that failed before it started (a bad url).
class ClosedConnection final : public Connection {
public:
    explicit ClosedConnection(std::string detail)
        : status_{ConnectionState::Closed, std::move(detail), 0} {}
    void send(const proto::ClientMessage&) override {}
    void send_text(const std::string&) override {}
    std::vector<proto::ServerMessage> poll() override { return {}; }
    bool wait(std::chrono::milliseconds) override { return false; }
    ConnectionStatus status() const override { return status_; }
    int decode_errors() const override { return 0; }
    void close() override {}

private:
    ConnectionStatus status_;
};

} // namespace

std::unique_ptr<Connection> Connection::open(const std::string& url,
                                             const ConnectionOptions& options) {
    auto parsed = parse_ws_url(url);
    if (auto* error = std::get_if<std::string>(&parsed)) {
        return std::make_unique<ClosedConnection>(std::move(*error));
    }
    std::shared_ptr<boost::asio::ssl::context> tls_context;
    if (std::get<WsUrl>(parsed).tls) {
        auto made = tls::client_tls_context(options.ca_file);
        if (auto* error = std::get_if<std::string>(&made)) {
            return std::make_unique<ClosedConnection>(std::move(*error));
        }
        tls_context = std::get<0>(std::move(made));
    }
    try {
        return std::make_unique<WsConnection>(std::get<WsUrl>(std::move(parsed)), options,
                                              std::move(tls_context));
    } catch (const std::exception& e) { // thread or socket creation failed
        return std::make_unique<ClosedConnection>(
            "Could not start a connection: " + std::string(e.what()) + ".");
    }
}

} // namespace carrom::net
