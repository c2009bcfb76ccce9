// client_address (server/src/client_address.hpp): the address the per-address limits count,
// the peer's or, from a trusted proxy, the last address of X-Forwarded-For; and the check of
// --trusted-proxy's entries.
#include "client_address.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace carrom::server {
namespace {

const std::vector<std::string> kFront = {"127.0.0.1"};

TEST(ClientAddress, WithoutTrustedProxiesThePeerCounts) {
    EXPECT_EQ(client_address("127.0.0.1", "203.0.113.7", {}), "127.0.0.1");
}

TEST(ClientAddress, ATrustedProxysLastForwardedAddressCounts) {
    EXPECT_EQ(client_address("127.0.0.1", "203.0.113.7", kFront), "203.0.113.7");
    // Addresses before the proxy's own entry came from the client: they count for nothing.
    EXPECT_EQ(client_address("127.0.0.1", "198.51.100.1, 203.0.113.7", kFront), "203.0.113.7");
    EXPECT_EQ(client_address("127.0.0.1", "198.51.100.1,203.0.113.7 ", kFront), "203.0.113.7");
    EXPECT_EQ(client_address("127.0.0.1", "2001:db8::5", kFront), "2001:db8::5");
}

TEST(ClientAddress, AnotherPeersHeaderIsIgnored) {
    EXPECT_EQ(client_address("192.0.2.9", "203.0.113.7", kFront), "192.0.2.9");
}

TEST(ClientAddress, NetworksAndMappedAddressesMatch) {
    const std::vector<std::string> nets = {"10.0.0.0/8", "fd00::/8"};
    EXPECT_EQ(client_address("10.1.2.3", "203.0.113.7", nets), "203.0.113.7");
    EXPECT_EQ(client_address("fd12::1", "203.0.113.7", nets), "203.0.113.7");
    EXPECT_EQ(client_address("11.1.2.3", "203.0.113.7", nets), "11.1.2.3");
    EXPECT_EQ(client_address("::ffff:10.0.0.1", "203.0.113.7", nets), "203.0.113.7");
    EXPECT_EQ(client_address("10.0.0.0", "203.0.113.7", {"10.0.0.0/32"}), "203.0.113.7");
}

TEST(ClientAddress, AHeaderThatDoesNotEndWithAnAddressIsIgnored) {
    EXPECT_EQ(client_address("127.0.0.1", "", kFront), "127.0.0.1");
    EXPECT_EQ(client_address("127.0.0.1", "203.0.113.7, unknown", kFront), "127.0.0.1");
    EXPECT_EQ(client_address("127.0.0.1", "203.0.113.7,", kFront), "127.0.0.1");
    EXPECT_EQ(client_address("127.0.0.1", "not an address", kFront), "127.0.0.1");
}

TEST(ClientAddress, EntriesThatAreNeitherAddressesNorNetworksAreNamed) {
    EXPECT_EQ(trusted_proxies_problem({"127.0.0.1", "10.0.0.0/8", "fd00::/8", "::1"}), "");
    EXPECT_EQ(trusted_proxies_problem({"127.0.0.1", "front"}),
              "--trusted-proxy \"front\" is not an IP address or network (10.0.0.0/8, fd00::/8)");
    EXPECT_NE(trusted_proxies_problem({"10.0.0.0/33"}), "");
    EXPECT_NE(trusted_proxies_problem({""}), "");
}

} // namespace
} // namespace carrom::server
