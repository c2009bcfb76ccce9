#include "load_redirect.hpp"

#include "carrom/net/redirect_rule.hpp"
#include "carrom/net/session_core.hpp"
#include "carrom/net/ws_url.hpp"

namespace carrom::load {

std::string load_url(const boost::asio::ip::tcp::endpoint& server, std::uint16_t port, bool tls) {
    const std::string address = server.address().is_v6() ? "[" + server.address().to_string() + "]"
                                                         : server.address().to_string();
    return (tls ? "wss://" : "ws://") + address + ":" + std::to_string(port);
}

std::variant<RedirectPlan, std::string>
plan_redirect(const LoadLink& link, const proto::Redirect& redirect, const std::string& token) {
    const std::string given = load_url(link.server, link.server.port(), link.tls);
    const std::string here = load_url(link.server, link.port, link.tls) + link.target;
    const std::string refused = "redirect refused: " + redirect.url;
    if (!net::redirect_allowed(here, given, redirect.url)) {
        return refused + " is not an address of this cluster (" + given + ").";
    }
    if (link.redirects >= net::SessionCore::kMaxRedirects) {
        return refused + ": more than " + std::to_string(net::SessionCore::kMaxRedirects) +
               " redirects in a row.";
    }
    const auto parsed = net::parse_ws_url(redirect.url);
    const auto* to = std::get_if<net::WsUrl>(&parsed);
    if (to == nullptr || to->tls != link.tls) {
        return refused + ": carrom-load follows only to its own scheme, with a port.";
    }
    return RedirectPlan{to->port,    to->target, redirect.code,
                        redirect.as, token,      link.redirects + 1};
}

} // namespace carrom::load
