#include "network_link.hpp"

#ifdef CARROM_CLIENT_HAS_NET
#include "carrom/net/connection.hpp"
#include "carrom/net/ws_url.hpp"

#include <variant>
#endif

#include <charconv>

namespace carrom::client::app {
#ifdef CARROM_CLIENT_HAS_NET
namespace {

// MessageLink over a net::Connection (WebSocket, its own I/O thread; thread-safe, so the UI
// thread calls it directly). The connection encodes, decodes and validates; frames that fail
// to decode are skipped there and only counted, which the status detail mentions.
class NetworkLink final : public MessageLink {
public:
    explicit NetworkLink(const std::string& url) : connection_(net::Connection::open(url)) {}
    ~NetworkLink() override = default; // the connection closes and joins its thread

    NetworkLink(const NetworkLink&) = delete;
    NetworkLink& operator=(const NetworkLink&) = delete;

    void send(const proto::ClientMessage& message) override { connection_->send(message); }
    std::vector<proto::ServerMessage> poll() override { return connection_->poll(); }
    LinkStatus status() const override {
        const net::ConnectionStatus s = connection_->status();
        LinkStatus out;
        switch (s.state) {
        case net::ConnectionState::Connecting:
            out.state = LinkState::Connecting;
            break;
        case net::ConnectionState::Open:
            out.state = LinkState::Open;
            break;
        case net::ConnectionState::Closed:
            out.state = LinkState::Closed;
            break;
        }
        out.detail = s.detail;
        if (const int bad = connection_->decode_errors(); bad > 0) {
            if (!out.detail.empty()) {
                out.detail += ' ';
            }
            out.detail += std::to_string(bad);
            out.detail += bad == 1 ? " message" : " messages";
            out.detail += " from the server could not be read and were ignored.";
        }
        return out;
    }
    void close() override { connection_->close(); }

private:
    std::unique_ptr<net::Connection> connection_;
};

} // namespace

std::string check_url(const std::string& url) {
    const auto parsed = net::parse_ws_url(url);
    if (const auto* problem = std::get_if<std::string>(&parsed)) {
        return *problem;
    }
    return {};
}

LinkFactory make_network_link_factory(const std::string& url) {
    return [url] { return std::make_unique<NetworkLink>(url); };
}

#else
namespace {

// The shape of a server address, for builds without net/ (which then refuse to connect anyway).
std::string check_url_shape(const std::string& url) {
    const std::string scheme = "ws://";
    if (url.rfind(scheme, 0) != 0) {
        return "The server address must start with ws:// (for example ws://127.0.0.1:8080).";
    }
    const std::string rest = url.substr(scheme.size());
    const std::string authority = rest.substr(0, rest.find('/'));
    const auto colon = authority.rfind(':');
    if (authority.empty() || colon == 0) {
        return "The server address has no host (for example ws://127.0.0.1:8080).";
    }
    if (colon != std::string::npos) {
        int port = 0;
        const char* first = authority.data() + colon + 1;
        const char* last = authority.data() + authority.size();
        const auto [end, ec] = std::from_chars(first, last, port);
        if (ec != std::errc() || end != last || port < 1 || port > 65535) {
            return "The server port must be a number from 1 to 65535.";
        }
    }
    return {};
}

class UnavailableLink final : public MessageLink {
public:
    void send(const proto::ClientMessage&) override {}
    std::vector<proto::ServerMessage> poll() override { return {}; }
    LinkStatus status() const override {
        return {LinkState::Closed, "This build of carrom-client has no network library "
                                   "(net/ was not built); try --demo"};
    }
    void close() override {}
};

} // namespace

std::string check_url(const std::string& url) {
    return check_url_shape(url);
}

LinkFactory make_network_link_factory(const std::string&) {
    return [] { return std::make_unique<UnavailableLink>(); };
}
#endif

} // namespace carrom::client::app
