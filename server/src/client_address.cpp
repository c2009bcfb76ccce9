#include "client_address.hpp"

#include <boost/asio/ip/address.hpp>
#include <boost/asio/ip/network_v4.hpp>
#include <boost/asio/ip/network_v6.hpp>

namespace carrom::server {
namespace {

namespace ip = boost::asio::ip;

std::string_view trim(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t')) {
        text.remove_prefix(1);
    }
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t')) {
        text.remove_suffix(1);
    }
    return text;
}

// Whether `address` is `entry` (an address) or inside it (a network). False for a bad entry.
bool matches(const ip::address& address, const std::string& entry) {
    boost::system::error_code ec;
    if (entry.find('/') == std::string::npos) {
        const ip::address single = ip::make_address(entry, ec);
        return !ec && single == address;
    }
    if (address.is_v4()) {
        const ip::network_v4 net = ip::make_network_v4(entry, ec);
        return !ec && (address.to_v4() == net.network() ||
                       ip::network_v4(address.to_v4(), 32).is_subnet_of(net));
    }
    const ip::network_v6 net = ip::make_network_v6(entry, ec);
    return !ec && (address.to_v6() == net.network() ||
                   ip::network_v6(address.to_v6(), 128).is_subnet_of(net));
}

} // namespace

std::string trusted_proxies_problem(const std::vector<std::string>& trusted) {
    for (const std::string& entry : trusted) {
        boost::system::error_code ec;
        if (entry.find('/') == std::string::npos) {
            (void)ip::make_address(entry, ec);
        } else if (entry.find(':') == std::string::npos) {
            (void)ip::make_network_v4(entry, ec);
        } else {
            (void)ip::make_network_v6(entry, ec);
        }
        if (ec) {
            return "--trusted-proxy \"" + entry +
                   "\" is not an IP address or network (10.0.0.0/8, fd00::/8)";
        }
    }
    return {};
}

std::string client_address(const std::string& peer, std::string_view forwarded_for,
                           const std::vector<std::string>& trusted) {
    if (trusted.empty() || forwarded_for.empty()) {
        return peer;
    }
    boost::system::error_code ec;
    ip::address peer_address = ip::make_address(peer, ec);
    if (ec) {
        return peer;
    }
    if (peer_address.is_v6() && peer_address.to_v6().is_v4_mapped()) {
        peer_address = ip::make_address_v4(ip::v4_mapped, peer_address.to_v6());
    }
    bool from_proxy = false;
    for (const std::string& entry : trusted) {
        from_proxy = from_proxy || matches(peer_address, entry);
    }
    if (!from_proxy) {
        return peer;
    }
    const auto comma = forwarded_for.rfind(',');
    const std::string last(
        trim(comma == std::string_view::npos ? forwarded_for : forwarded_for.substr(comma + 1)));
    const ip::address client = ip::make_address(last, ec);
    return ec ? peer : client.to_string();
}

} // namespace carrom::server
