#include "carrom/net/ws_url.hpp"

#include "quoted_url.hpp"

#include <algorithm>

namespace carrom::net {

namespace {

bool host_char_ok(char c) {
    const auto u = static_cast<unsigned char>(c);
    return u > 0x20 && u != 0x7f && c != '/' && c != '?' && c != '#' && c != '@';
}

// Parses PORT (decimal, 1..65535) or returns nothing.
std::optional<std::uint16_t> parse_port(std::string_view text) {
    if (text.empty() || text.size() > 5) {
        return std::nullopt;
    }
    int value = 0;
    for (char c : text) {
        if (c < '0' || c > '9') {
            return std::nullopt;
        }
        value = value * 10 + (c - '0');
    }
    if (value < 1 || value > 65535) {
        return std::nullopt;
    }
    return static_cast<std::uint16_t>(value);
}

} // namespace

std::string WsUrl::authority() const {
    const bool ipv6 = host.find(':') != std::string::npos;
    return (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

std::variant<WsUrl, std::string> parse_ws_url(std::string_view url) {
    constexpr std::string_view kScheme = "ws://";
    constexpr std::string_view kTlsScheme = "wss://";
    const std::string bad = "The server address " + quoted_url(url);
    const bool tls = url.substr(0, kTlsScheme.size()) == kTlsScheme;
    if (!tls && url.substr(0, kScheme.size()) != kScheme) {
        return bad + " must start with ws:// or wss:// (for example ws://127.0.0.1:7777).";
    }
    std::string_view rest = url.substr(tls ? kTlsScheme.size() : kScheme.size());
    if (rest.find('#') != std::string_view::npos) {
        return bad + " must not have a #fragment.";
    }
    const auto slash = rest.find_first_of("/?");
    std::string_view authority = rest.substr(0, slash);
    WsUrl out;
    if (slash != std::string_view::npos) {
        out.target = rest[slash] == '/' ? "" : "/";
        out.target.append(rest.substr(slash));
        if (std::any_of(out.target.begin(), out.target.end(), [](char c) {
                return static_cast<unsigned char>(c) <= 0x20 || c == 0x7f;
            })) {
            return bad + " has a space or a control character in its path.";
        }
    }
    std::string_view host;
    std::string_view port;
    if (!authority.empty() && authority.front() == '[') {
        const auto close = authority.find(']');
        if (close == std::string_view::npos) {
            return bad + " has an IPv6 address without its closing ].";
        }
        host = authority.substr(1, close - 1);
        const auto after = authority.substr(close + 1);
        if (after.empty() || after.front() != ':') {
            return bad + " needs a port after the address, as in ws://[::1]:7777.";
        }
        port = after.substr(1);
    } else {
        const auto colon = authority.rfind(':');
        if (colon == std::string_view::npos) {
            return bad + " needs a port, as in ws://127.0.0.1:7777.";
        }
        host = authority.substr(0, colon);
        port = authority.substr(colon + 1);
        if (host.find(':') != std::string_view::npos) {
            return bad + " must put an IPv6 address in brackets, as in ws://[::1]:7777.";
        }
    }
    if (host.empty()) {
        return bad + " has no host name.";
    }
    if (host.size() > 253 || !std::all_of(host.begin(), host.end(), host_char_ok)) {
        return bad + " has a host name that is too long or holds a character not allowed there.";
    }
    const auto port_number = parse_port(port);
    if (!port_number) {
        return bad + " has a port that is not a number from 1 to 65535.";
    }
    out.host = std::string(host);
    out.port = *port_number;
    out.tls = tls;
    return out;
}

std::string quoted_url(std::string_view url) {
    constexpr std::size_t kShown = 80;
    std::string shown(url.substr(0, kShown));
    std::replace_if(
        shown.begin(), shown.end(),
        [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }, '?');
    return "'" + shown + (url.size() > kShown ? "...'" : "'");
}

} // namespace carrom::net
