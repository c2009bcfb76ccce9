#pragma once
// Helpers for the store tests: a temporary directory removed afterwards, a file's bytes,
// journals of games played by the rules (tests/proto/journal_support.hpp), and StoreTest, the
// fixture of the suites that run on both backends (a test named Suite.Case/sqlite and
// Suite.Case/postgres): an SQLite file in a temporary directory, or a new database on the
// test binary's own PostgreSQL server (postgres_server(), started at its first use and stopped
// when the binary ends).

#include "proto/journal_support.hpp"
#include "store/open_match_store.hpp"
#include "store/sqlite_match_store.hpp"
#include "support/postgres_instance.hpp"

#include <SQLiteCpp/Database.h>
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace carrom::store::test {

namespace fs = std::filesystem;

// A fresh directory under the test temp dir, removed with everything in it at the end.
class TempDir {
public:
    TempDir() {
        std::string pattern = (fs::path(::testing::TempDir()) / "carrom_store_XXXXXX").string();
        path_ = ::mkdtemp(pattern.data());
    }
    ~TempDir() {
        std::error_code ec;
        fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, ec);
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string file(const std::string& name) const { return (fs::path(path_) / name).string(); }
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

inline std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
}

inline void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

// Short retries so that failure tests finish quickly.
inline SqliteStoreOptions fast_options() {
    SqliteStoreOptions options;
    options.retry_initial = std::chrono::milliseconds(5);
    options.retry_max = std::chrono::milliseconds(20);
    options.checkpoint_interval = std::chrono::milliseconds(50);
    options.close_timeout = std::chrono::milliseconds(2000);
    return options;
}

inline std::unique_ptr<SqliteMatchStore> open_store(const std::string& path,
                                                    SqliteStoreOptions options = fast_options()) {
    auto opened = SqliteMatchStore::open(path, std::move(options));
    EXPECT_FALSE(opened.error.has_value()) << opened.error->code << ": " << opened.error->message;
    return std::move(opened.store);
}

inline proto::MatchCreated created(const std::string& id, const std::string& first = "ann",
                                   const std::string& second = "bea") {
    proto::MatchCreated c = proto::test::make_created(rules::RuleSet::Icf, {}, id);
    c.seats = {proto::JournalSeat{first, false}, proto::JournalSeat{second, false}};
    return c;
}

// Writes a whole journal: create, then every entry in order.
inline void store_journal(MatchStore& store, const proto::MatchJournal& journal) {
    store.create(journal.created);
    for (std::size_t i = 0; i < journal.entries.size(); ++i) {
        store.append(journal.created.match_id, static_cast<std::int64_t>(i), journal.entries[i]);
    }
}

constexpr std::chrono::milliseconds kFlush{10000};

// The test binary's PostgreSQL server: started at the first call (a gtest Environment stops it
// and removes its directory when the tests end).
test_support::PostgresInstance& postgres_server();

// A test that runs on each backend: GetParam() is "sqlite" or "postgres".
class StoreTest : public ::testing::TestWithParam<std::string> {
protected:
    bool postgres() const { return GetParam() == "postgres"; }
    // The test's store location: an SQLite file (not yet created) or a new empty database.
    const std::string& location() {
        if (location_.empty()) {
            location_ = new_location();
        }
        return location_;
    }
    std::string new_location() {
        if (postgres()) {
            return postgres_server().url(postgres_server().create_database());
        }
        return dir_.file("carrom" + std::to_string(++files_) + ".db");
    }
    OpenedStore try_open(StoreOptions options = fast_options()) {
        return open_match_store(location(), std::move(options));
    }
    std::unique_ptr<MatchStore> open(StoreOptions options = fast_options()) {
        auto opened = try_open(std::move(options));
        EXPECT_FALSE(opened.error.has_value())
            << opened.error->code << ": " << opened.error->message;
        return std::move(opened.store);
    }

    // The database's name on the PostgreSQL server (postgres() only).
    std::string database() {
        const std::string& url = location();
        const std::size_t start = url.find("@/") + 2;
        return url.substr(start, url.find('?') - start);
    }
    // Runs SQL on the database as its owner (SQLite: creating the file if needed).
    void execute(const std::string& statements) {
        if (postgres()) {
            const auto ran = postgres_server().sql(database(), statements);
            ASSERT_EQ(ran.exit, 0) << ran.out;
        } else {
            SQLite::Database db(location(), SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
            db.exec(statements);
        }
    }
    // Everything the database holds, to compare before and after: the SQLite file's bytes, or
    // the PostgreSQL database dumped as SQL text (pg_dump; bytea as hex; without the random
    // key of its \restrict lines).
    std::string snapshot() {
        if (postgres()) {
            return test_support::run_command(test_support::PostgresInstance::bindir() +
                                             "/pg_dump -h " + postgres_server().directory() +
                                             " -U carrom " + database() +
                                             " | grep -v -e '^.restrict ' -e '^.unrestrict '")
                .out;
        }
        return read_bytes(location());
    }

    TempDir dir_;

private:
    std::string location_;
    int files_ = 0;
};

inline std::string backend_name(const ::testing::TestParamInfo<std::string>& info) {
    return info.param;
}

} // namespace carrom::store::test

// Instantiates a StoreTest suite on both backends.
#define CARROM_STORE_BACKENDS(Suite)                                                               \
    INSTANTIATE_TEST_SUITE_P(, Suite, ::testing::Values("sqlite", "postgres"),                     \
                             ::carrom::store::test::backend_name)

namespace carrom::store::test {} // namespace carrom::store::test
