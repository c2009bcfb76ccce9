// carrom-load: drives N concurrent two-player matches against one carrom-server on 127.0.0.1
// and measures what docs/server-load.md reports: matches held, messages per second, snapshot lag
// p50/p99, bytes per client per second while pieces move, server memory per match and CPU.
// Bounded: at most 5,000 matches and 7,200 s of measurement; 127.0.0.1 only.
#include "load_client.hpp"
#include "load_process.hpp"

#include "carrom/proto/limits.hpp"
#include "carrom/tls/client_tls.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <future>
#include <iostream>
#include <map>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace {

using namespace carrom;
using load::cpu_seconds;
using load::fetch_metrics;
using load::rss_kib;
using load::spawn_server;
namespace asio = boost::asio;
using tcp = asio::ip::tcp;

// The server's own snapshot send lag: the bucket bound holding quantile q of the increase.
std::string server_lag_quantile(const std::map<std::string, double>& before,
                                const std::map<std::string, double>& after, double q) {
    std::vector<std::pair<double, double>> buckets; // (bound s, count increase)
    double total = 0.0;
    for (const auto& [name, value] : after) {
        const std::string prefix = "carrom_snapshot_lag_seconds_bucket{le=\"";
        if (name.rfind(prefix, 0) != 0) {
            continue;
        }
        const std::string label = name.substr(prefix.size(), name.size() - prefix.size() - 2);
        const double bound = label == "+Inf" ? 1e9 : std::stod(label);
        const auto it = before.find(name);
        const double increase = value - (it == before.end() ? 0.0 : it->second);
        buckets.emplace_back(bound, increase);
        total = std::max(total, increase);
    }
    std::sort(buckets.begin(), buckets.end());
    for (const auto& [bound, count] : buckets) { // cumulative buckets
        if (total > 0.0 && count >= q * total) {
            return bound >= 1e9 ? "> 100 ms" : "<= " + std::to_string(bound * 1000.0) + " ms";
        }
    }
    return "n/a";
}

double delta(const std::map<std::string, double>& before,
             const std::map<std::string, double>& after, const std::string& name) {
    const auto a = after.find(name);
    const auto b = before.find(name);
    return (a == after.end() ? 0.0 : a->second) - (b == before.end() ? 0.0 : b->second);
}

double quantile(std::vector<double> values, double q) {
    if (values.empty()) {
        return 0.0;
    }
    const auto k = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
}

// Lag per second of the window, by due time: [second, samples, p99 ms, max ms] rows, so a stall
// shows where it happened rather than only in the percentiles of the whole window.
nlohmann::json lag_timeline(const std::vector<double>& lag_ms,
                            const std::vector<std::int64_t>& due_ms, std::int64_t window_start_ms,
                            double duration_s) {
    const auto seconds = static_cast<std::size_t>(std::ceil(duration_s));
    std::vector<std::vector<double>> by_second(seconds);
    for (std::size_t i = 0; i < lag_ms.size() && i < due_ms.size(); ++i) {
        const std::int64_t offset_ms = due_ms[i] - window_start_ms;
        if (offset_ms >= 0 && static_cast<std::size_t>(offset_ms / 1000) < seconds) {
            by_second[static_cast<std::size_t>(offset_ms / 1000)].push_back(lag_ms[i]);
        }
    }
    nlohmann::json rows = nlohmann::json::array();
    for (std::size_t s = 0; s < seconds; ++s) {
        rows.push_back(
            {s, by_second[s].size(), quantile(by_second[s], 0.99), quantile(by_second[s], 1.0)});
    }
    return rows;
}

template <class F> auto on_io(asio::io_context& ioc, F f) {
    std::promise<decltype(f())> promise;
    auto future = promise.get_future();
    asio::post(ioc, [&] { promise.set_value(f()); });
    return future.get();
}

double load_average() {
    std::ifstream in("/proc/loadavg");
    double value = 0.0;
    in >> value;
    return value;
}

// The running totals of one shard, for the progress lines.
struct Totals {
    std::int64_t held = 0;
    load::LoadCounts counts;
    Totals& operator+=(const Totals& other) {
        held += other.held;
        counts += other.counts;
        return *this;
    }
};

void raise_fd_limit() {
    rlimit limit{};
    if (getrlimit(RLIMIT_NOFILE, &limit) == 0) {
        limit.rlim_cur = limit.rlim_max;
        setrlimit(RLIMIT_NOFILE, &limit);
    }
}

} // namespace

int main(int argc, char** argv) {
    std::string server_bin;
    std::vector<std::string> server_args;
    int port = 0;
    int server_pid = 0;
    int matches = 100;
    double ramp_s = 5.0;
    double warmup_s = 5.0;
    double duration_s = 20.0;
    int think_ms = 0;
    int think_spread_ms = 0;
    std::string rule_set_name = "freestyle";
    std::uint64_t seed = 1;
    std::string json_out;
    int client_threads = 2;
    int target_points = 1000;
    bool replace = false;
    bool no_samples = false;
    std::string progress_out;
    double progress_s = 60.0;
    bool tls = false;
    std::string ca_file;

    CLI::App app{"carrom-load: N concurrent bot matches against a carrom-server on 127.0.0.1"};
    app.option_defaults()->always_capture_default();
    auto* spawn = app.add_option("--server-bin", server_bin,
                                 "Start this carrom-server (127.0.0.1, ephemeral port)");
    app.add_option("--server-arg", server_args, "Extra argument for the started server")
        ->needs(spawn);
    auto* port_option =
        app.add_option("--port", port, "Port of a running server on 127.0.0.1")->excludes(spawn);
    app.add_option("--server-pid", server_pid, "Its process id (memory and CPU)")
        ->needs(port_option);
    app.add_option("--matches", matches, "Concurrent matches")->check(CLI::Range(1, 5000));
    app.add_option("--ramp", ramp_s, "Seconds over which matches start")
        ->check(CLI::Range(0.0, 120.0));
    app.add_option("--warmup", warmup_s, "Seconds after the ramp before measuring")
        ->check(CLI::Range(0.0, 120.0));
    app.add_option("--duration", duration_s, "Seconds measured")->check(CLI::Range(1.0, 7200.0));
    app.add_option("--think-ms", think_ms,
                   "Delay before each shot, ms (0: the board is nearly "
                   "always moving)")
        ->check(CLI::Range(0, 60000));
    app.add_option("--think-spread-ms", think_spread_ms,
                   "Each delay is drawn uniformly within this of --think-ms (players out of step)")
        ->check(CLI::Range(0, 60000));
    app.add_option("--rule-set", rule_set_name, "Rule set")
        ->check(CLI::IsMember({"icf", "seed", "freestyle", "discpool"}));
    app.add_option("--seed", seed, "Random seed of the players");
    app.add_option("--client-threads", client_threads, "Threads for the clients")
        ->check(CLI::Range(1, 16));
    app.add_option("--json-out", json_out, "Also write the JSON result here");
    app.add_option("--target-points", target_points, "Points that win a game")
        ->check(CLI::Range(1, proto::kMaxTargetPoints));
    app.add_flag("--replace", replace,
                 "When a game ends both players leave and a new match starts in its place "
                 "(default: a rematch in the same room)");
    app.add_flag("--no-samples", no_samples,
                 "Keep no per-snapshot lag samples (long runs); the lag figures are then 0");
    app.add_option("--progress-out", progress_out,
                   "Append a JSON line of running totals here every --progress-s seconds");
    app.add_option("--progress-s", progress_s, "Seconds between progress lines")
        ->check(CLI::Range(1.0, 3600.0));
    auto* tls_flag = app.add_flag("--tls", tls,
                                  "Connect with wss (TLS; the server's certificate must be for "
                                  "127.0.0.1 and trusted)");
    app.add_option("--ca-file", ca_file, "--tls: trust the certificate authorities in this file")
        ->needs(tls_flag);
    CLI11_PARSE(app, argc, argv);
    if (think_spread_ms > think_ms) {
        std::cerr << "--think-spread-ms must not exceed --think-ms.\n";
        return 2;
    }
    if (server_bin.empty() && port == 0) {
        std::cerr << "Give --server-bin PATH, or --port PORT [--server-pid PID].\n";
        return 2;
    }

    raise_fd_limit(); // inherited by a started server
    pid_t pid = server_pid;
    if (!server_bin.empty()) {
        const auto spawned = spawn_server(server_bin, server_args);
        if (!spawned) {
            std::cerr << "Could not start " << server_bin << ".\n";
            return 1;
        }
        pid = spawned->pid;
        port = spawned->port;
    }
    const auto server_port = static_cast<std::uint16_t>(port);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    const long rss_idle = pid > 0 ? rss_kib(pid) : 0;

    load::LoadOptions options;
    options.server = {asio::ip::make_address("127.0.0.1"), server_port};
    if (tls) {
        auto context = tls::client_tls_context(ca_file);
        if (auto* error = std::get_if<std::string>(&context)) {
            std::cerr << *error << "\n";
            return 2;
        }
        options.tls = std::get<0>(std::move(context));
    }
    proto::parse(rule_set_name, options.rule_set);
    options.think = std::chrono::milliseconds(think_ms);
    options.think_spread = std::chrono::milliseconds(think_spread_ms);
    options.target_points = target_points;
    options.replace = replace;
    options.keep_samples = !no_samples;
    // Shards: each client thread runs its own io_context with its own matches and stats, so
    // nothing is shared between threads.
    struct Shard {
        asio::io_context ioc{1};
        load::LoadStats stats;
        std::vector<std::unique_ptr<load::MatchPair>> pairs;
        std::thread thread;
    };
    std::vector<std::unique_ptr<Shard>> shards;
    for (int i = 0; i < client_threads; ++i) {
        shards.push_back(std::make_unique<Shard>());
    }
    std::vector<asio::executor_work_guard<asio::io_context::executor_type>> guards;
    for (auto& shard : shards) {
        guards.push_back(asio::make_work_guard(shard->ioc));
        shard->thread = std::thread([s = shard.get()] { s->ioc.run(); });
    }

    // Ramp: start the matches evenly over ramp_s.
    const auto ramp_start = load::Clock::now();
    for (int i = 0; i < matches; ++i) {
        const auto at = ramp_start + std::chrono::duration_cast<load::Clock::duration>(
                                         std::chrono::duration<double>(ramp_s * i / matches));
        std::this_thread::sleep_until(at);
        Shard& shard = *shards[static_cast<std::size_t>(i % client_threads)];
        auto pair = std::make_unique<load::MatchPair>(
            shard.ioc, options, shard.stats, seed * 100000 + static_cast<std::uint64_t>(i));
        asio::post(shard.ioc, [&shard, p = std::move(pair)]() mutable {
            p->start();
            shard.pairs.push_back(std::move(p));
        });
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(warmup_s));

    // Measure.
    auto held_in = [](Shard& shard) {
        return std::count_if(shard.pairs.begin(), shard.pairs.end(),
                             [](const auto& p) { return p->held(); });
    };
    const auto metrics_before = fetch_metrics(server_port);
    const double cpu_before = pid > 0 ? cpu_seconds(pid) : 0.0;
    const double own_cpu_before = cpu_seconds(getpid());
    std::int64_t held_before = 0;
    for (auto& shard : shards) {
        held_before += on_io(shard->ioc, [&] {
            shard->stats.measuring = true;
            return static_cast<std::int64_t>(held_in(*shard));
        });
    }
    const auto start = load::Clock::now();
    const auto end = start + std::chrono::duration_cast<load::Clock::duration>(
                                 std::chrono::duration<double>(duration_s));
    if (!progress_out.empty()) {
        std::ofstream progress(progress_out, std::ios::app);
        const auto every = std::chrono::duration_cast<load::Clock::duration>(
            std::chrono::duration<double>(progress_s));
        for (auto next = start + every; next <= end; next += every) {
            std::this_thread::sleep_until(next);
            Totals totals;
            for (auto& shard : shards) {
                totals += on_io(shard->ioc, [&] {
                    return Totals{static_cast<std::int64_t>(held_in(*shard)),
                                  static_cast<const load::LoadCounts&>(shard->stats)};
                });
            }
            const nlohmann::json line = {
                {"t_s", std::chrono::duration<double>(load::Clock::now() - start).count()},
                {"held", totals.held},
                {"matches_started", totals.counts.matches_started},
                {"matches_finished", totals.counts.matches_finished},
                {"errors_received", totals.counts.errors},
                {"client_failures", totals.counts.failures},
                {"shots", totals.counts.shots},
                {"messages", totals.counts.messages}};
            progress << line.dump() << std::endl;
        }
    }
    std::this_thread::sleep_until(end);
    const long rss_loaded = pid > 0 ? rss_kib(pid) : 0;
    std::int64_t held = 0;
    load::LoadStats measured;
    for (auto& shard : shards) {
        const auto [h, stats] = on_io(shard->ioc, [&] {
            shard->stats.measuring = false;
            return std::make_pair(static_cast<std::int64_t>(held_in(*shard)), shard->stats);
        });
        held += h;
        measured += stats;
    }
    const double elapsed = std::chrono::duration<double>(load::Clock::now() - start).count();
    const double cpu_after = pid > 0 ? cpu_seconds(pid) : 0.0;
    const double own_cpu_after = cpu_seconds(getpid());
    const auto metrics_after = fetch_metrics(server_port);

    // Wind down: everyone leaves, then the server stops.
    for (auto& shard : shards) {
        asio::post(shard->ioc, [s = shard.get()] {
            for (auto& p : s->pairs) {
                p->close();
            }
        });
    }
    std::this_thread::sleep_for(std::chrono::seconds(1));
    guards.clear();
    for (auto& shard : shards) {
        shard->ioc.stop();
        shard->thread.join();
    }
    int server_exit = 0;
    if (!server_bin.empty()) {
        kill(pid, SIGTERM);
        int status = 0;
        waitpid(pid, &status, 0);
        server_exit = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }

    const double clients = 2.0 * static_cast<double>(matches);
    nlohmann::json out = {
        {"matches", matches},
        {"rule_set", rule_set_name},
        {"think_ms", think_ms},
        {"think_spread_ms", think_spread_ms},
        {"client_threads", client_threads},
        {"target_points", target_points},
        {"replace", replace},
        {"matches_started", measured.matches_started},
        {"matches_finished", measured.matches_finished},
        {"errors_by_code", measured.errors_by_code},
        {"duration_s", elapsed},
        {"held_at_start", held_before},
        {"held_at_end", held},
        {"client_failures", measured.failures},
        {"tls", tls},
        {"tls_refusal", measured.tls_refusal},
        {"redirects", measured.redirects},
        {"redirects_refused", measured.redirects_refused},
        {"redirect_refusal", measured.redirect_refusal},
        {"errors_received", measured.errors},
        {"messages_malformed", measured.malformed},
        {"shots", measured.shots},
        {"shots_per_s", static_cast<double>(measured.shots) / elapsed},
        {"client_messages_per_s", static_cast<double>(measured.messages) / elapsed},
        {"server_messages_out_per_s",
         delta(metrics_before, metrics_after, "carrom_messages_out_total") / elapsed},
        {"server_messages_in_per_s",
         delta(metrics_before, metrics_after, "carrom_messages_in_total") / elapsed},
        {"snapshots_per_s", static_cast<double>(measured.snapshots) / elapsed},
        {"snapshot_lag_ms_p50", quantile(measured.lag_ms, 0.50)},
        {"snapshot_lag_ms_p99", quantile(measured.lag_ms, 0.99)},
        {"snapshot_lag_ms_max", quantile(measured.lag_ms, 1.0)},
        {"lag_samples", measured.lag_ms.size()},
        {"lag_by_second", lag_timeline(measured.lag_ms, measured.lag_due_ms,
                                       std::chrono::duration_cast<std::chrono::milliseconds>(
                                           start.time_since_epoch())
                                           .count(),
                                       elapsed)},
        {"relative_lag_ms_p50", quantile(measured.relative_lag_ms, 0.50)},
        {"relative_lag_ms_p99", quantile(measured.relative_lag_ms, 0.99)},
        {"server_send_lag_p50", server_lag_quantile(metrics_before, metrics_after, 0.50)},
        {"server_send_lag_p99", server_lag_quantile(metrics_before, metrics_after, 0.99)},
        {"snapshots_dropped",
         delta(metrics_before, metrics_after, "carrom_snapshots_dropped_total")},
        {"bytes_per_client_per_s_moving",
         measured.moving_seconds > 0 ? measured.moving_bytes / measured.moving_seconds : 0.0},
        {"bytes_per_client_per_s_overall", static_cast<double>(measured.bytes) / elapsed / clients},
        {"server_rss_idle_kib", rss_idle},
        {"server_rss_loaded_kib", rss_loaded},
        {"server_kib_per_match",
         matches > 0 ? static_cast<double>(rss_loaded - rss_idle) / matches : 0.0},
        {"server_cpu_percent", 100.0 * (cpu_after - cpu_before) / elapsed},
        {"client_cpu_percent", 100.0 * (own_cpu_after - own_cpu_before) / elapsed},
        {"loadavg_1min", load_average()},
        {"server_exit", server_exit},
    };
    std::cout << out.dump(2) << std::endl;
    if (!json_out.empty()) {
        std::ofstream(json_out) << out.dump(2) << "\n";
    }
    // With --replace a slot may be between two matches at the end (not yet seated).
    return measured.failures == 0 && (replace || held == matches) ? 0 : 1;
}
