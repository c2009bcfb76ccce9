// Opening the store on each backend, where both refuse alike: a store opens again with what it
// holds; a database written by a newer carrom-server, and one that holds another program's
// tables, are refused with one line naming it and left exactly as they were; a second store on
// the same database is locked out until the first closes.

#include "store_support.hpp"

#include "store/postgres_database.hpp"
#include "store/sqlite_database.hpp"

namespace carrom::store {
namespace {

using StoreOpen = test::StoreTest;
CARROM_STORE_BACKENDS(StoreOpen);

// Expects a refusal with code, in one line naming the location (the PostgreSQL URLs of the
// tests have no password to hide); returns the message.
std::string expect_refused(OpenedStore opened, std::string_view code, const std::string& location) {
    EXPECT_EQ(opened.store, nullptr);
    if (!opened.error) {
        ADD_FAILURE() << location << " was accepted";
        return "";
    }
    EXPECT_EQ(opened.error->code, code) << opened.error->message;
    EXPECT_NE(opened.error->message.find(location), std::string::npos) << opened.error->message;
    EXPECT_EQ(opened.error->message.find('\n'), std::string::npos) << opened.error->message;
    return opened.error->message;
}

void store_games(MatchStore& store, int matches) {
    for (int i = 0; i < matches; ++i) {
        proto::MatchJournal journal =
            proto::test::random_game(rules::RuleSet::Icf, static_cast<std::uint64_t>(i + 1))
                .journal();
        journal.created.match_id = "m" + std::to_string(i);
        test::store_journal(store, journal);
    }
    ASSERT_TRUE(store.flush(test::kFlush));
}

TEST_P(StoreOpen, AStoreOpensAgainWithItsContents) {
    store_games(*open(), 2);
    auto store = open();
    ASSERT_NE(store, nullptr);
    EXPECT_TRUE(store->journal("m0").value.has_value());
    EXPECT_TRUE(store->journal("m1").value.has_value());
    EXPECT_FALSE(store->journal("m2").value.has_value());
    EXPECT_EQ(store->health().backend, postgres() ? "postgresql" : "sqlite");
}

TEST_P(StoreOpen, ANewerSchemaIsRefusedAndUntouched) {
    store_games(*open(), 1);
    const int known = postgres() ? store::postgres::kSchemaVersion : store::sqlite::kSchemaVersion;
    const std::string newer = std::to_string(known + 1);
    execute(postgres() ? "UPDATE carrom_schema SET version = " + newer
                       : "PRAGMA user_version = " + newer);
    const std::string before = snapshot();
    EXPECT_EQ(expect_refused(try_open(), "store_newer_schema", location()),
              location() + " was written by a newer carrom-server (schema version " + newer +
                  "; this one knows up to " + std::to_string(known) + ")");
    EXPECT_EQ(snapshot(), before);
}

TEST_P(StoreOpen, AnotherProgramsDatabaseIsRefusedAndUntouched) {
    execute("CREATE TABLE notes (text TEXT)");
    const std::string before = snapshot();
    EXPECT_EQ(expect_refused(try_open(), "store_foreign", location()),
              location() + (postgres() ? " holds another program's tables (notes)"
                                       : " is a SQLite database of another program (it has "
                                         "tables but not the carrom application_id)"));
    EXPECT_EQ(snapshot(), before);
}

TEST_P(StoreOpen, ASecondStoreOnTheSameDatabaseIsLockedOut) {
    auto first = open();
    ASSERT_NE(first, nullptr);
    EXPECT_EQ(expect_refused(try_open(), "store_locked", location()),
              postgres()
                  ? "cannot use " + location() +
                        ": another carrom-server holds it (its advisory lock 1129467210)"
                  : "cannot use " + location() + ": another carrom-server uses it (it holds " +
                        location() + ".lock)");
    first.reset();
    EXPECT_NE(open(), nullptr);
}

} // namespace
} // namespace carrom::store
