// Opening the SQLite store against real files in a temporary directory: a new file is created in
// WAL mode with the current schema; every file the store must refuse (a directory, a file that is
// not a database, a corrupt or truncated database, another program's marked database, a
// read-only file, an unwritable directory) gives its own code and one line naming the path, and
// the file's bytes are unchanged. What both backends refuse alike (a newer schema, another
// program's tables, a second server) is in store_open_test.cpp.

#include "store_support.hpp"

#include "store/sqlite_database.hpp"

#include <SQLiteCpp/Database.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

namespace carrom::store {
namespace {

using test::read_bytes;
using test::TempDir;
using test::write_bytes;

// Opens path and expects the error code; returns the message.
std::string expect_refused(const std::string& path, std::string_view code) {
    auto opened = SqliteMatchStore::open(path, test::fast_options());
    EXPECT_EQ(opened.store, nullptr);
    if (!opened.error) {
        ADD_FAILURE() << path << " was accepted";
        return "";
    }
    EXPECT_EQ(opened.error->code, code) << opened.error->message;
    EXPECT_NE(opened.error->message.find(path), std::string::npos) << opened.error->message;
    EXPECT_EQ(opened.error->message.find('\n'), std::string::npos) << opened.error->message;
    return opened.error->message;
}

// The open error code seen by an unprivileged user (nobody) when this process runs as root, whose
// writes no permission stops; in-process otherwise.
std::string refusal_code_unprivileged(const std::string& path) {
    if (::geteuid() != 0) {
        auto opened = SqliteMatchStore::open(path, test::fast_options());
        return opened.error ? opened.error->code : "accepted";
    }
    int fds[2];
    if (::pipe(fds) != 0) {
        return "pipe failed";
    }
    const pid_t child = ::fork();
    if (child == 0) {
        ::close(fds[0]);
        std::string code = "setuid failed";
        if (::setgid(65534) == 0 && ::setuid(65534) == 0) {
            auto opened = SqliteMatchStore::open(path, test::fast_options());
            code = opened.error ? opened.error->code : "accepted";
        }
        const auto written = ::write(fds[1], code.data(), code.size());
        ::_exit(written == static_cast<ssize_t>(code.size()) ? 0 : 1);
    }
    ::close(fds[1]);
    std::string code;
    char buffer[256];
    ssize_t got = 0;
    while ((got = ::read(fds[0], buffer, sizeof buffer)) > 0) {
        code.append(buffer, static_cast<std::size_t>(got));
    }
    ::close(fds[0]);
    int status = 0;
    ::waitpid(child, &status, 0);
    return code;
}

// A store with a few journals in it, closed (its WAL checkpointed into the file).
void make_store(const std::string& path, int matches = 3) {
    auto store = test::open_store(path);
    ASSERT_NE(store, nullptr);
    for (int i = 0; i < matches; ++i) {
        auto game =
            proto::test::random_game(rules::RuleSet::Icf, static_cast<std::uint64_t>(i + 1));
        proto::MatchJournal journal = game.journal();
        journal.created.match_id = "m" + std::to_string(i);
        test::store_journal(*store, journal);
    }
    ASSERT_TRUE(store->flush(test::kFlush));
}

TEST(SqliteStoreOpen, ANewFileIsCreatedWithItsDirectoryInWalModeAtTheCurrentSchema) {
    TempDir dir;
    const std::string path = dir.file("data/sub/carrom.db");
    {
        auto store = test::open_store(path);
        ASSERT_NE(store, nullptr);
        EXPECT_EQ(store->path(), path);
    }
    SQLite::Database db(path, SQLite::OPEN_READONLY);
    EXPECT_EQ(db.execAndGet("PRAGMA journal_mode").getString(), "wal");
    EXPECT_EQ(db.execAndGet("PRAGMA user_version").getInt(), sqlite::kSchemaVersion);
    EXPECT_EQ(db.execAndGet("PRAGMA application_id").getInt(), sqlite::kApplicationId);
    EXPECT_TRUE(db.tableExists("matches"));
    EXPECT_TRUE(db.tableExists("entries"));
    EXPECT_TRUE(db.tableExists("players"));
    EXPECT_TRUE(db.tableExists("seat_tokens"));
}

TEST(SqliteStoreOpen, AnEmptyFileBecomesAStore) {
    TempDir dir;
    const std::string path = dir.file("carrom.db");
    write_bytes(path, "");
    {
        auto store = test::open_store(path);
        ASSERT_NE(store, nullptr);
    }
    SQLite::Database db(path, SQLite::OPEN_READONLY);
    EXPECT_EQ(db.execAndGet("PRAGMA user_version").getInt(), sqlite::kSchemaVersion);
}

TEST(SqliteStoreOpen, ADirectoryIsRefused) {
    TempDir dir;
    const std::string path = dir.file("carrom.db");
    test::fs::create_directory(path);
    EXPECT_EQ(expect_refused(path, "store_is_directory"), path + " is a directory, not a file");
    EXPECT_TRUE(test::fs::is_empty(path));
}

TEST(SqliteStoreOpen, AFileThatIsNotADatabaseIsRefusedAndUntouched) {
    TempDir dir;
    const std::string path = dir.file("carrom.db");
    std::string text;
    for (int i = 0; i < 200; ++i) {
        text += "these are not the pages you are looking for\n";
    }
    write_bytes(path, text);
    EXPECT_EQ(expect_refused(path, "store_not_a_database"), path + " is not a SQLite database");
    EXPECT_EQ(read_bytes(path), text);
    // Nothing was created next to it either (no WAL, no lock file).
    EXPECT_EQ(
        std::distance(test::fs::directory_iterator(dir.path()), test::fs::directory_iterator()), 1);
}

TEST(SqliteStoreOpen, ACorruptDatabaseIsRefusedAndUntouched) {
    TempDir dir;
    const std::string path = dir.file("carrom.db");
    make_store(path);
    std::string bytes = read_bytes(path);
    ASSERT_GT(bytes.size(), 4U * 4096U);
    for (std::size_t i = 2 * 4096; i < 3 * 4096; ++i) { // all of page 3
        bytes[i] = static_cast<char>(0xa5);
    }
    write_bytes(path, bytes);
    expect_refused(path, "store_corrupt");
    EXPECT_EQ(read_bytes(path), bytes);
}

TEST(SqliteStoreOpen, ATruncatedDatabaseIsRefusedAndUntouched) {
    TempDir dir;
    const std::string path = dir.file("carrom.db");
    make_store(path);
    const std::string half = read_bytes(path).substr(0, read_bytes(path).size() / 2);
    write_bytes(path, half);
    expect_refused(path, "store_corrupt");
    EXPECT_EQ(read_bytes(path), half);
}

TEST(SqliteStoreOpen, ADatabaseCutInsideItsHeaderIsRefusedAndUntouched) {
    TempDir dir;
    const std::string path = dir.file("carrom.db");
    make_store(path);
    const std::string head = read_bytes(path).substr(0, 60);
    write_bytes(path, head);
    expect_refused(path, "store_corrupt");
    EXPECT_EQ(read_bytes(path), head);
}

// (Another program's tables without a mark: StoreOpen.AnotherProgramsDatabaseIsRefused...)
TEST(SqliteStoreOpen, ADatabaseMarkedByAnotherProgramIsRefusedAndUntouched) {
    TempDir dir;
    const std::string marked = dir.file("marked.db");
    {
        SQLite::Database db(marked, SQLite::OPEN_READWRITE | SQLite::OPEN_CREATE);
        db.exec("PRAGMA application_id = 305419896"); // 0x12345678
    }
    const std::string marked_bytes = read_bytes(marked);
    EXPECT_EQ(expect_refused(marked, "store_foreign"),
              marked + " is a SQLite database of another program (application_id 0x12345678)");
    EXPECT_EQ(read_bytes(marked), marked_bytes);
}

TEST(SqliteStoreOpen, AReadOnlyFileIsRefusedAndUntouched) {
    TempDir dir;
    const std::string path = dir.file("carrom.db");
    make_store(path, 1);
    ::chmod(dir.path().c_str(), 0755);
    ::chmod(path.c_str(), 0444);
    const std::string bytes = read_bytes(path);
    EXPECT_EQ(refusal_code_unprivileged(path), "store_read_only");
    EXPECT_EQ(read_bytes(path), bytes);
}

TEST(SqliteStoreOpen, AFileInAReadOnlyDirectoryIsRefused) {
    TempDir dir;
    const std::string path = dir.file("carrom.db");
    make_store(path, 1);
    ::chmod(path.c_str(), 0666);
    ::chmod(dir.path().c_str(), 0555); // the WAL and the lock file could not be created
    const std::string bytes = read_bytes(path);
    EXPECT_EQ(refusal_code_unprivileged(path), "store_read_only");
    EXPECT_EQ(read_bytes(path), bytes);
}

TEST(SqliteStoreOpen, ANewFileInAnUnwritableDirectoryIsRefused) {
    TempDir dir;
    ::chmod(dir.path().c_str(), 0555);
    EXPECT_EQ(refusal_code_unprivileged(dir.file("carrom.db")), "store_cannot_create");
}

TEST(SqliteStoreOpen, APathUnderAFileIsRefused) {
    TempDir dir;
    write_bytes(dir.file("plain"), "x");
    const std::string path = dir.file("plain/carrom.db");
    expect_refused(path, "store_cannot_create");
}

} // namespace
} // namespace carrom::store
