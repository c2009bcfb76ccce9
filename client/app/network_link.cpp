#include "network_link.hpp"

#include "carrom/net/connection.hpp"
#include "carrom/net/ws_url.hpp"

#include <random>
#include <variant>

namespace carrom::client::app {
namespace {

// MessageLink over a net::Connection (WebSocket, its own I/O thread; thread-safe, so the UI
// thread calls it directly). The connection encodes, decodes and validates; frames that fail
// to decode are skipped there and only counted, which the status detail mentions.
class NetworkLink final : public MessageLink {
public:
    NetworkLink(const std::string& url, const net::ConnectionOptions& options)
        : connection_(net::Connection::open(url, options)) {}
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
        out.close_code = s.close_code;
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

SessionConfig network_session_config(const std::optional<std::string>& identity,
                                     const std::string& address) {
    SessionConfig config;
    config.address = address;
    config.jitter_seed = std::random_device{}();
    config.identity = identity;
    return config;
}

LinkFactory make_network_link_factory(const std::string& ca_file) {
    net::ConnectionOptions options;
    options.ca_file = ca_file;
    return
        [options](const std::string& url) { return std::make_unique<NetworkLink>(url, options); };
}

} // namespace carrom::client::app
