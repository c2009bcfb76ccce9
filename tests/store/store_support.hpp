#pragma once
// Helpers for the store tests: a temporary directory removed afterwards, a file's bytes, and
// journals of games played by the rules (tests/proto/journal_support.hpp).

#include "proto/journal_support.hpp"
#include "store/sqlite_match_store.hpp"

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

} // namespace carrom::store::test
