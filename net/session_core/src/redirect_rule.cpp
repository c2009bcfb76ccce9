#include "carrom/net/redirect_rule.hpp"

#include <algorithm>

namespace carrom::net {
namespace {

constexpr std::string_view kWs = "ws://";
constexpr std::string_view kWss = "wss://";

bool starts_with(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

} // namespace

std::string ws_url_host(std::string_view url) {
    const bool tls = starts_with(url, kWss);
    if (!tls && !starts_with(url, kWs)) {
        return {};
    }
    if (std::any_of(url.begin(), url.end(),
                    [](char c) { return static_cast<unsigned char>(c) <= 0x20 || c == 0x7f; })) {
        return {};
    }
    const std::string_view rest = url.substr(tls ? kWss.size() : kWs.size());
    const std::string_view authority = rest.substr(0, rest.find_first_of("/?#"));
    if (authority.find('@') != std::string_view::npos) {
        return {};
    }
    std::string_view host;
    if (starts_with(authority, "[")) {
        const auto close = authority.find(']');
        host =
            close == std::string_view::npos ? std::string_view() : authority.substr(0, close + 1);
    } else {
        host = authority.substr(0, authority.find(':'));
    }
    std::string out(host);
    std::transform(out.begin(), out.end(), out.begin(), [](char c) {
        return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
    });
    return out == "[]" ? std::string() : out;
}

bool redirect_allowed(std::string_view from_url, std::string_view address,
                      std::string_view to_url) {
    const std::string host = ws_url_host(to_url);
    if (host.empty() || host != ws_url_host(address)) {
        return false;
    }
    return !starts_with(from_url, kWss) || starts_with(to_url, kWss); // never a downgrade
}

} // namespace carrom::net
