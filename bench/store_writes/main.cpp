// carrom-store-writes: appends stroke entries to a match store (SQLite, or PostgreSQL with a
// postgresql:// URL as --path) at a steady rate (or as fast as it takes them) and reports how long
// each append waited for its on_written(true): the time a room would hold a stroke's first
// broadcast back (docs/store.md).
//   carrom-store-writes --matches 1000 --rate 300 --seconds 10 [--path FILE|URL]
// prints one line: the time open() took (its checks include PRAGMA quick_check, which reads
// every page), entries, entries/s achieved, and the wait's p50, p99, p99.9 and max in ms.
// --rate 0 appends as fast as possible (throughput). The entries are real journal entries of a
// seeded game, so their size is a stroke's.

#include "carrom/proto/journal_replay.hpp"
#include "carrom/rules/match.hpp"
#include "store/open_match_store.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using namespace carrom;
using Clock = std::chrono::steady_clock;

// The entries of a few strokes of a real game (their JSON is a stroke's size).
std::vector<proto::JournalEntry> sample_strokes() {
    rules::MatchState state = rules::new_match(rules::RuleSet::Icf, {}, {});
    ExactEngine engine(state.physics);
    std::vector<proto::JournalEntry> out;
    std::mt19937_64 rng(1);
    for (int i = 0; i < 16; ++i) {
        const double x = 200.0 + static_cast<double>(rng() % 200);
        const Shot shot{x, -1.2 - 0.05 * static_cast<double>(rng() % 14), 18.0};
        const rules::PlayResult r = rules::play_shot(state, state.turn_seat, shot, engine);
        if (r.error) {
            continue;
        }
        out.push_back(proto::stroke_entry(1700000000000 + i, r));
        state = r.state;
        if (state.phase == rules::Phase::BoardOver) {
            state = rules::start_next_board(state);
        }
        if (state.phase == rules::Phase::GameOver) {
            break;
        }
    }
    return out;
}

double percentile(std::vector<double>& v, double p) {
    if (v.empty()) {
        return 0.0;
    }
    const auto k = static_cast<std::size_t>(p * static_cast<double>(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
    return v[k];
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"carrom-store-writes: the match store's write latency and throughput"};
    int matches = 1000;
    double rate = 300.0;
    double seconds = 10.0;
    std::string path;
    app.add_option("--matches", matches, "matches appended to in turn")
        ->check(CLI::Range(1, 100000));
    app.add_option("--rate", rate, "entries per second, 0 = as fast as possible")
        ->check(CLI::Range(0.0, 1e7));
    app.add_option("--seconds", seconds, "duration")->check(CLI::Range(0.1, 3600.0));
    app.add_option("--path", path,
                   "database file or PostgreSQL URL (default: a new file in a temp directory)");
    CLI11_PARSE(app, argc, argv);

    std::filesystem::path dir;
    if (path.empty()) {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "carrom_store_XXXXXX").string();
        dir = ::mkdtemp(pattern.data());
        path = (dir / "carrom.db").string();
    }
    const auto open_start = Clock::now();
    auto opened = store::open_match_store(path);
    const double open_ms =
        std::chrono::duration<double, std::milli>(Clock::now() - open_start).count();
    if (opened.error) {
        std::fprintf(stderr, "%s: %s\n", opened.error->code.c_str(), opened.error->message.c_str());
        return 2;
    }
    store::MatchStore& s = *opened.store;
    const std::vector<proto::JournalEntry> strokes = sample_strokes();
    std::vector<std::int64_t> next_seq(static_cast<std::size_t>(matches), 0);
    std::vector<std::string> ids;
    for (int m = 0; m < matches; ++m) {
        proto::MatchCreated c;
        c.match_id = "bench-" + std::to_string(m) + "-" +
                     std::to_string(open_start.time_since_epoch().count());
        c.room_code = "ABCDEF";
        c.seats = {proto::JournalSeat{"ann", false}, proto::JournalSeat{"bea", false}};
        c.versions.server = "bench";
        ids.push_back(c.match_id);
        s.create(c);
    }
    s.flush(std::chrono::seconds(60));

    std::mutex mutex;
    std::vector<double> waits_ms;
    std::atomic<std::int64_t> acked{0};
    const auto start = Clock::now();
    const auto end =
        start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    std::int64_t sent = 0;
    while (Clock::now() < end) {
        if (rate > 0.0) {
            const auto due =
                start + std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double>(static_cast<double>(sent) / rate));
            std::this_thread::sleep_until(due);
        } else if (sent - acked.load() > 100000) {
            std::this_thread::yield(); // as fast as possible, within the store's memory bound
            continue;
        }
        const auto m = static_cast<std::size_t>(sent % matches);
        const auto queued = Clock::now();
        s.append(ids[m], next_seq[m]++, strokes[static_cast<std::size_t>(sent) % strokes.size()],
                 [&, queued](bool written) {
                     const double ms =
                         std::chrono::duration<double, std::milli>(Clock::now() - queued).count();
                     acked.fetch_add(1);
                     if (written) {
                         const std::lock_guard lock(mutex);
                         waits_ms.push_back(ms);
                     }
                 });
        ++sent;
    }
    s.flush(std::chrono::seconds(60));
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    const store::StoreHealth health = s.health();
    opened.store.reset();
    if (!dir.empty()) {
        std::filesystem::remove_all(dir);
    }
    const std::lock_guard lock(mutex);
    const std::size_t written = waits_ms.size();
    std::printf("open_ms %.1f matches %d entries %lld written %zu entries_per_s %.0f wait_ms p50 "
                "%.3f p99 %.3f "
                "p99.9 %.3f max %.3f errors %llu\n",
                open_ms, matches, static_cast<long long>(sent), written,
                static_cast<double>(written) / elapsed, percentile(waits_ms, 0.5),
                percentile(waits_ms, 0.99), percentile(waits_ms, 0.999), percentile(waits_ms, 1.0),
                static_cast<unsigned long long>(health.errors_total));
    return 0;
}
