#include "network_link.hpp"

#include <charconv>

namespace carrom::client::app {

std::string check_url(const std::string& url) {
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

#ifndef CARROM_CLIENT_HAS_NET
namespace {

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

LinkFactory make_network_link_factory(const std::string&) {
    return [] { return std::make_unique<UnavailableLink>(); };
}
#endif

} // namespace carrom::client::app
