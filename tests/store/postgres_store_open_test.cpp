// Opening the PostgreSQL store where only a networked database can fail: a new database gets the
// schema (with the ownership columns reserved for cluster mode, empty in single-instance mode); a
// schema 1 database gets the ratings tables and keeps its matches; a URL libpq refuses, a server
// that is not there, a database that does not exist, a role that may not log in and a role
// without rights on the database are refused with their own code and one line naming the URL (its
// password hidden), and leave the database as it was.

#include "store_support.hpp"

#include "store/postgres_match_store.hpp"
#include "store/postgres_url.hpp"

namespace carrom::store {
namespace {

// Opens url and expects the error code; returns the message.
std::string expect_pg_refused(const std::string& url, std::string_view code) {
    auto opened = PostgresMatchStore::open(url, test::fast_options());
    EXPECT_EQ(opened.store, nullptr);
    if (!opened.error) {
        ADD_FAILURE() << url << " was accepted";
        return "";
    }
    EXPECT_EQ(opened.error->code, code) << opened.error->message;
    EXPECT_EQ(opened.error->message.find('\n'), std::string::npos) << opened.error->message;
    return opened.error->message;
}

std::string query(const std::string& database, const std::string& sql) {
    const auto ran = test::postgres_server().sql(database, sql);
    EXPECT_EQ(ran.exit, 0) << ran.out;
    return ran.out;
}

// A store opened on the database, match m1 created in it, the store closed.
void store_one_match(const std::string& database) {
    auto opened =
        PostgresMatchStore::open(test::postgres_server().url(database), test::fast_options());
    ASSERT_NE(opened.store, nullptr) << opened.error->message;
    opened.store->create(test::created("m1"));
    ASSERT_TRUE(opened.store->flush(test::kFlush));
}

TEST(PostgresStoreOpen, ANewDatabaseGetsTheSchemaWithTheClusterColumnsAndInstances) {
    const std::string database = test::postgres_server().create_database();
    ASSERT_NO_FATAL_FAILURE(store_one_match(database));
    EXPECT_EQ(query(database, "SELECT application, version FROM carrom_schema"),
              "carrom-match-store|5\n");
    EXPECT_EQ(query(database, "SELECT table_name FROM information_schema.tables WHERE "
                              "table_schema = 'public' ORDER BY table_name"),
              "carrom_schema\nentries\nidentities\ninstances\nmatches\nplayers\nquick_tickets\n"
              "rated_seats\nrating_changes\nratings\nrooms\nseat_tokens\n");
    EXPECT_EQ(query(database, "SELECT id, owner_instance IS NULL, owner_epoch FROM matches"),
              "m1|t|0\n");
}

TEST(PostgresStoreOpen, ASchemaOneDatabaseGetsTheRatingsAndClusterTablesAndKeepsItsMatches) {
    const std::string database = test::postgres_server().create_database();
    ASSERT_NO_FATAL_FAILURE(store_one_match(database));
    // Back to schema 1: without migration 2's, 3's, 4's and 5's tables.
    query(database, "DROP TABLE rating_changes, rated_seats, ratings, identities, instances, "
                    "rooms, quick_tickets; DROP INDEX matches_owner, matches_open_room, "
                    "seat_tokens_hash; ALTER TABLE matches DROP COLUMN handed_over; "
                    "UPDATE carrom_schema SET version = 1");
    auto opened =
        PostgresMatchStore::open(test::postgres_server().url(database), test::fast_options());
    ASSERT_NE(opened.store, nullptr) << opened.error->message;
    EXPECT_EQ(query(database, "SELECT version FROM carrom_schema"), "5\n");
    EXPECT_EQ(query(database, "SELECT count(*) FROM information_schema.tables WHERE "
                              "table_schema = 'public' AND table_name IN ('identities', "
                              "'ratings', 'rated_seats', 'rating_changes', 'instances', 'rooms', "
                              "'quick_tickets')"),
              "7\n");
    EXPECT_TRUE(opened.store->journal("m1").value.has_value());
    EXPECT_TRUE(opened.store->load_players().ok());
}

TEST(PostgresStoreOpen, AUrlLibpqRefusesIsABadUrl) {
    const std::string url = "postgresql://carrom@/t?host=/tmp&no_such_option=1";
    EXPECT_EQ(expect_pg_refused(url, "store_bad_url"),
              url + " is not a PostgreSQL URL libpq accepts: invalid URI query parameter: "
                    "\"no_such_option\"");
    EXPECT_EQ(expect_pg_refused("postgresql://carrom@[::1/t", "store_bad_url")
                  .find("postgresql://carrom@[::1/t is not a PostgreSQL URL libpq accepts: "),
              0U);
}

TEST(PostgresStoreOpen, AServerThatIsNotThereCannotBeConnectedTo) {
    test::TempDir empty; // no socket in it
    const std::string url = "postgresql://carrom@/t?host=" + empty.path();
    const std::string message = expect_pg_refused(url, "store_cannot_connect");
    EXPECT_EQ(message.find("cannot connect to " + url + ": "), 0U) << message;
}

TEST(PostgresStoreOpen, ADatabaseThatDoesNotExistCannotBeConnectedTo) {
    const std::string url = test::postgres_server().url("no_such_database");
    EXPECT_EQ(expect_pg_refused(url, "store_cannot_connect"),
              "cannot connect to " + url + ": connection to server on socket \"" +
                  test::postgres_server().directory() +
                  "/.s.PGSQL.5432\" failed: FATAL:  database \"no_such_database\" does not "
                  "exist");
}

TEST(PostgresStoreOpen, ARoleThatMayNotLogInIsRefused) {
    auto& server = test::postgres_server();
    const std::string database = server.create_database();
    query("postgres", "CREATE ROLE cannot_log_in NOLOGIN");
    const std::string message =
        expect_pg_refused(server.url(database, "cannot_log_in"), "store_permission");
    EXPECT_NE(message.find("role \"cannot_log_in\" is not permitted to log in"), std::string::npos)
        << message;
}

// PostgreSQL 15 lets only the owner create in the public schema: a role that may log in but has
// no rights there cannot create the tables, and nothing is written.
TEST(PostgresStoreOpen, ARoleWithoutRightsOnTheDatabaseIsRefusedAndNothingIsWritten) {
    auto& server = test::postgres_server();
    const std::string database = server.create_database();
    query("postgres", "CREATE ROLE no_rights LOGIN");
    const std::string url = server.url(database, "no_rights");
    EXPECT_EQ(expect_pg_refused(url, "store_permission"),
              "preparing " + url + ": permission denied for schema public");
    EXPECT_EQ(query(database, "SELECT count(*) FROM information_schema.tables WHERE "
                              "table_schema = 'public'"),
              "0\n");
}

// A role that may read the tables but not write them: the store does not open.
TEST(PostgresStoreOpen, ARoleThatMayOnlyReadIsRefused) {
    auto& server = test::postgres_server();
    const std::string database = server.create_database();
    {
        auto opened = PostgresMatchStore::open(server.url(database), test::fast_options());
        ASSERT_NE(opened.store, nullptr) << opened.error->message;
    }
    query(database, "CREATE ROLE reader LOGIN; GRANT SELECT ON ALL TABLES IN SCHEMA public TO "
                    "reader");
    const std::string url = server.url(database, "reader");
    EXPECT_EQ(expect_pg_refused(url, "store_permission"),
              "cannot use " + url + ": role reader may not INSERT on table matches");
}

TEST(PostgresStoreOpen, APasswordInTheUrlIsNeverShown) {
    const std::string url = test::postgres_server().url("no_such_database", "carrom:s3cret");
    const std::string message = expect_pg_refused(url, "store_cannot_connect");
    EXPECT_EQ(message.find("s3cret"), std::string::npos) << message;
    EXPECT_NE(message.find("postgresql://carrom:***@/no_such_database"), std::string::npos)
        << message;
    EXPECT_EQ(postgres::shown_url("postgres://u:p@h:5/d?x=1"), "postgres://u:***@h:5/d?x=1");
    EXPECT_EQ(postgres::shown_url("postgresql://u@h/d"), "postgresql://u@h/d");
    EXPECT_EQ(postgres::shown_url("postgresql:///d?host=/a:b@c"), "postgresql:///d?host=/a:b@c");
}

} // namespace
} // namespace carrom::store
