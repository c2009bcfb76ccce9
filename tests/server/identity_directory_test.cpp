// How identified players' names compare (player_name_key.hpp) and who may hold one
// (identity_directory.hpp): docs/ratings.md, "Names" and "Abuse".
#include "identity_directory.hpp"
#include "player_name_key.hpp"

#include "store/match_store.hpp"

#include <gtest/gtest.h>

namespace carrom::server {
namespace {

TEST(PlayerNameKey, CaseWidthIgnorablesAndSpacesDoNotMakeANewName) {
    const std::string asha = *player_name_key("Asha");
    EXPECT_EQ(asha, "asha");
    EXPECT_EQ(player_name_key("ASHA"), asha);
    EXPECT_EQ(player_name_key("\xef\xbc\xa1\xef\xbd\x93\xef\xbd\x88\xef\xbd\x81"),
              asha);                                      // fullwidth
    EXPECT_EQ(player_name_key("As\xe2\x80\x8bha"), asha); // a zero-width space inside
    EXPECT_EQ(player_name_key("  Asha "), asha);
    EXPECT_EQ(player_name_key("Asha  Rao"), player_name_key("asha rao"));
    EXPECT_EQ(player_name_key("Jos\xc3\xa9"), player_name_key("Jose\xcc\x81")); // NFC == NFD
    EXPECT_EQ(player_name_key("STRASSE"), player_name_key("stra\xc3\x9f"
                                                          "e")); // sharp s folds
}

TEST(PlayerNameKey, DifferentLettersStayDifferentNames) {
    EXPECT_NE(player_name_key("Asha"), player_name_key("Usha"));
    EXPECT_NE(player_name_key("Jose"), player_name_key("Jos\xc3\xa9"));
    EXPECT_EQ(player_name_key("\xe0\xa4\x85\xe0\xa4\xb6\xe0\xa4\xbe"),
              std::string("\xe0\xa4\x85\xe0\xa4\xb6\xe0\xa4\xbe")); // Devanagari is kept
}

TEST(PlayerNameKey, NoKeyForInvalidOrInvisibleNames) {
    EXPECT_FALSE(player_name_key("\xff").has_value());
    EXPECT_FALSE(player_name_key("   ").has_value());
    EXPECT_FALSE(player_name_key("\xe2\x80\x8b").has_value()); // only a zero-width space
}

TEST(IdentityDirectory, ANameBelongsToOneIdentityUntilItRenames) {
    IdentityDirectory directory;
    const auto ann = store::hash_token("ann's key");
    const auto bea = store::hash_token("bea's key");
    const auto first = directory.claim(ann, "Ann", "10.0.0.1", 1000, 0);
    ASSERT_TRUE(std::holds_alternative<IdentityDirectory::Claimed>(first));
    EXPECT_TRUE(std::get<IdentityDirectory::Claimed>(first).changed);
    const auto again = directory.claim(ann, "Ann", "10.0.0.1", 2000, 0);
    EXPECT_FALSE(std::get<IdentityDirectory::Claimed>(again).changed);
    const auto taken = directory.claim(bea, "ANN", "10.0.0.2", 3000, 0);
    ASSERT_TRUE(std::holds_alternative<proto::Error>(taken));
    EXPECT_EQ(std::get<proto::Error>(taken).code, "name_taken");
    EXPECT_EQ(directory.check_guest_name("ann")->code, "name_taken");
    const auto renamed = directory.claim(ann, "Annie", "10.0.0.1", 4000, 0);
    EXPECT_TRUE(std::get<IdentityDirectory::Claimed>(renamed).changed);
    EXPECT_EQ(std::get<IdentityDirectory::Claimed>(renamed).player.created_ms, 1000);
    EXPECT_FALSE(directory.check_guest_name("Ann").has_value());
    EXPECT_TRUE(std::holds_alternative<IdentityDirectory::Claimed>(
        directory.claim(bea, "Ann", "10.0.0.2", 5000, 0)));
}

TEST(IdentityDirectory, NewIdentitiesPerAddressAreLimitedPerMinute) {
    IdentityDirectory directory;
    for (int i = 0; i < 5; ++i) {
        const auto key = store::hash_token("key " + std::to_string(i));
        EXPECT_TRUE(std::holds_alternative<IdentityDirectory::Claimed>(
            directory.claim(key, "P" + std::to_string(i), "10.0.0.9", 0, 0)));
    }
    const auto sixth = directory.claim(store::hash_token("key 5"), "P5", "10.0.0.9", 0, 0);
    ASSERT_TRUE(std::holds_alternative<proto::Error>(sixth));
    EXPECT_EQ(std::get<proto::Error>(sixth).code, "too_many_identities");
    // Another address is not limited by this one; 12 s later this one has one more.
    EXPECT_TRUE(std::holds_alternative<IdentityDirectory::Claimed>(
        directory.claim(store::hash_token("key 6"), "P6", "10.0.0.10", 0, 0)));
    EXPECT_TRUE(std::holds_alternative<IdentityDirectory::Claimed>(
        directory.claim(store::hash_token("key 5"), "P5", "10.0.0.9", 0, 12000)));
    EXPECT_EQ(directory.size(), 7U);
}

} // namespace
} // namespace carrom::server
