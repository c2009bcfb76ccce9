// carrom-server: the authoritative game server. Flags fall back to CARROM_* environment
// variables; see docs/server.md.
#include "carrom/server/server.hpp"
#include "carrom/server/web_assets.hpp"
#include "store/open_match_store.hpp"
#include "store/postgres_url.hpp"

#include "bot_brains.hpp"

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <memory>

int main(int argc, char** argv) {
    carrom::server::ServerSettings s;
    std::string log_level = "info";
    std::uint64_t bot_seed = 1;
    int bot_think_ms = 300;
    bool no_bots = false;
    std::string web_root;
    bool no_web = false;
    std::string data = "carrom-data/carrom.db";
    CLI::App app{"carrom-server: authoritative carrom game server (WebSocket + HTTP)"};
    app.option_defaults()->always_capture_default();
    app.add_option("--host", s.host, "Address to listen on (0.0.0.0 serves other machines)")
        ->envname("CARROM_HOST");
    app.add_option("--port", s.port, "Port (0 = ephemeral; the bound port is printed either way)")
        ->envname("CARROM_PORT");
    app.add_option("--threads", s.threads, "I/O threads")
        ->envname("CARROM_THREADS")
        ->check(CLI::Range(1, 256));
    app.add_option("--snapshot-hz", s.snapshot_hz,
                   "Regular snapshots per second while pieces move (besides the contact ones)")
        ->envname("CARROM_SNAPSHOT_HZ")
        ->check(CLI::Range(1.0, 240.0));
    app.add_option("--contact-snapshots", s.contact_snapshots,
                   "A snapshot at every change of motion (contact, stop, pocketing): "
                   "true or false")
        ->envname("CARROM_CONTACT_SNAPSHOTS");
    app.add_option("--time-scale", s.time_scale,
                   "Match seconds per wall second while a shot plays (tests; 1 = real time)")
        ->envname("CARROM_TIME_SCALE")
        ->check(CLI::Range(0.01, 1000.0));
    app.add_option("--max-message-bytes", s.max_message_bytes, "Largest client message, bytes")
        ->envname("CARROM_MAX_MESSAGE_BYTES")
        ->check(CLI::Range(256, 1 << 20));
    app.add_option("--max-rate", s.max_rate, "Client messages per second (sustained)")
        ->envname("CARROM_MAX_RATE")
        ->check(CLI::Range(1.0, 10000.0));
    app.add_option("--rate-burst", s.rate_burst, "Client message burst allowance")
        ->envname("CARROM_RATE_BURST")
        ->check(CLI::Range(1.0, 100000.0));
    app.add_option("--handshake-timeout", s.handshake_timeout_s,
                   "Seconds for the WebSocket upgrade and for hello")
        ->envname("CARROM_HANDSHAKE_TIMEOUT")
        ->check(CLI::Range(0.05, 3600.0));
    app.add_option("--idle-timeout", s.idle_timeout_s,
                   "Seconds without any frame before closing (pings at half of it)")
        ->envname("CARROM_IDLE_TIMEOUT")
        ->check(CLI::Range(0.1, 86400.0));
    app.add_option("--max-connections", s.max_connections, "Open WebSocket connections")
        ->envname("CARROM_MAX_CONNECTIONS")
        ->check(CLI::Range(1, 1000000));
    app.add_option("--max-connections-per-address", s.max_connections_per_address,
                   "Open WebSocket connections from one client address")
        ->envname("CARROM_MAX_CONNECTIONS_PER_ADDRESS")
        ->check(CLI::Range(1, 1000000));
    std::string trusted_proxies;
    app.add_option("--trusted-proxy", trusted_proxies,
                   "Proxies (IP addresses or networks, comma-separated) whose X-Forwarded-For "
                   "names the client address the per-address limits count")
        ->envname("CARROM_TRUSTED_PROXY");
    app.add_option("--max-rooms", s.max_rooms, "Open rooms")
        ->envname("CARROM_MAX_ROOMS")
        ->check(CLI::Range(1, 1000000));
    app.add_option("--grace", s.grace_s, "Seconds a dropped player keeps the seat")
        ->envname("CARROM_GRACE")
        ->check(CLI::Range(0.0, 86400.0));
    app.add_option("--shot-clock", s.shot_clock_s, "Default seconds per stroke (0 = off)")
        ->envname("CARROM_SHOT_CLOCK")
        ->check(CLI::Range(0.0, 600.0));
    app.add_option("--bot-shot-clock", s.bot_shot_clock_s,
                   "Default seconds per stroke in a room with a server bot (at least --shot-clock)")
        ->envname("CARROM_BOT_SHOT_CLOCK")
        ->check(CLI::Range(0.0, 600.0));
    app.add_option("--shutdown-grace", s.shutdown_grace_s,
                   "Seconds to close connections on SIGINT/SIGTERM")
        ->envname("CARROM_SHUTDOWN_GRACE")
        ->check(CLI::Range(0.0, 60.0));
    app.add_option("--http-rate", s.http_rate,
                   "Match API and /metrics requests per second per client address (sustained)")
        ->envname("CARROM_HTTP_RATE")
        ->check(CLI::Range(0.01, 100000.0));
    app.add_option("--http-burst", s.http_burst,
                   "Match API and /metrics request burst allowance per client address")
        ->envname("CARROM_HTTP_BURST")
        ->check(CLI::Range(1.0, 100000.0));
    auto* tls_cert = app.add_option("--tls-cert", s.tls_cert,
                                    "TLS certificate chain, PEM (https and wss on the port, "
                                    "beside plain http and ws; re-read on SIGHUP)")
                         ->envname("CARROM_TLS_CERT");
    app.add_option("--tls-key", s.tls_key, "TLS private key of --tls-cert, PEM (unencrypted)")
        ->envname("CARROM_TLS_KEY")
        ->needs(tls_cert);
    tls_cert->needs("--tls-key");
    app.add_option("--tls-handshake-timeout", s.tls_handshake_timeout_s,
                   "Seconds for a new connection's first bytes and TLS handshake")
        ->envname("CARROM_TLS_HANDSHAKE_TIMEOUT")
        ->check(CLI::Range(0.05, 600.0));
    app.add_option("--bot-seed", bot_seed, "Seed of the first server-side bot's random choices")
        ->envname("CARROM_BOT_SEED");
    app.add_option("--bot-think-ms", bot_think_ms,
                   "Time budget of a server-side bot's decision, ms (queueing included)")
        ->envname("CARROM_BOT_THINK_MS")
        ->check(CLI::Range(10, 60000));
    app.add_option("--quick-match-bot", s.quick_match_bot_s,
                   "Seconds a quick-match player waits for a partner before a bot is seated "
                   "(0 = never)")
        ->envname("CARROM_QUICK_MATCH_BOT")
        ->check(CLI::Range(0.0, 86400.0));
    std::string quick_bot_level{carrom::proto::to_string(s.quick_match_bot_level)};
    app.add_option("--quick-match-bot-level", quick_bot_level,
                   "Level of the quick-match bot: random, easy, medium, hard")
        ->envname("CARROM_QUICK_MATCH_BOT_LEVEL")
        ->check(CLI::IsMember({"random", "easy", "medium", "hard"}));
    app.add_flag("--no-bots", no_bots, "Refuse rooms that ask for a bot seat (\"unsupported\")")
        ->envname("CARROM_NO_BOTS");
    auto* web_root_option =
        app.add_option("--web-root", web_root,
                       "Serve the web client from this directory instead of the embedded copy")
            ->envname("CARROM_WEB_ROOT");
    app.add_flag("--no-web", no_web, "Do not serve the web client (404)")
        ->envname("CARROM_NO_WEB")
        ->excludes(web_root_option);
    app.add_option("--data", data,
                   "Match store: the SQLite database file (created on first start), a "
                   "PostgreSQL URL (postgresql://USER@HOST[:PORT]/DB), or none")
        ->envname("CARROM_DATA");
    carrom::store::postgres::ClusterOptions cluster;
    double lease_s = 10.0;
    app.add_option("--instance-id", cluster.instance_id,
                   "With a PostgreSQL store: this instance's id in the cluster, 1-64 of "
                   "[A-Za-z0-9._-] (default: HOSTNAME-XXXXXX, generated and logged)")
        ->envname("CARROM_INSTANCE_ID");
    app.add_option("--public-url", cluster.public_url,
                   "With a PostgreSQL store (required): the ws:// or wss:// URL clients reach "
                   "this instance at")
        ->envname("CARROM_PUBLIC_URL");
    app.add_option("--lease", lease_s,
                   "With a PostgreSQL store: seconds a lease lasts (renewed every third of it); "
                   "a dead instance's matches are taken over after it")
        ->envname("CARROM_LEASE");
    app.add_option("--log-level", log_level, "trace, debug, info, warn, error, off")
        ->envname("CARROM_LOG_LEVEL")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "off"}));
    CLI11_PARSE(app, argc, argv);
    (void)carrom::proto::parse(quick_bot_level, s.quick_match_bot_level);
    if (const std::string problem = carrom::server::tls_files_problem(s); !problem.empty()) {
        std::fprintf(stderr, "carrom-server: bad_tls_files: %s\n", problem.c_str());
        return 2;
    }
    for (std::size_t at = 0; at < trusted_proxies.size();) {
        const std::size_t comma = std::min(trusted_proxies.find(',', at), trusted_proxies.size());
        s.trusted_proxies.push_back(trusted_proxies.substr(at, comma - at));
        at = comma + 1;
    }
    if (const std::string problem = carrom::server::trusted_proxies_problem(s); !problem.empty()) {
        std::fprintf(stderr, "carrom-server: bad_trusted_proxy: %s\n", problem.c_str());
        return 2;
    }

    // Logs go to stderr: stdout carries only the "listening on" line that scripts read.
    spdlog::set_default_logger(std::make_shared<spdlog::logger>(
        "", std::make_shared<spdlog::sinks::stderr_color_sink_mt>()));
    spdlog::set_level(spdlog::level::from_str(log_level));
    std::shared_ptr<const carrom::server::StaticSite> web;
    if (!web_root.empty()) {
        auto load = carrom::server::StaticSite::from_directory(web_root);
        if (!load.site) {
            std::fprintf(stderr, "carrom-server: bad_web_root: %s\n", load.error.c_str());
            return 2;
        }
        web = std::make_shared<const carrom::server::StaticSite>(std::move(*load.site));
    } else if (!no_web) {
        web = std::make_shared<const carrom::server::StaticSite>(
            carrom::server::StaticSite::from_files(carrom::server::embedded_web_files()));
    }
    std::shared_ptr<carrom::store::MatchStore> store;
    if (data != "none") {
        carrom::store::StoreOptions options;
        // Test seam (docs/store.md, "Write errors"): writes fail while this file exists.
        if (const char* fail_file = std::getenv("CARROM_TEST_STORE_FAIL_FILE");
            fail_file != nullptr && *fail_file != '\0') {
            options.fail_writes = [path = std::string(fail_file)] {
                std::error_code ec;
                return std::filesystem::exists(path, ec);
            };
            spdlog::warn("test seam: match store writes fail while {} exists", fail_file);
        }
        const bool postgres = carrom::store::postgres::is_postgres_url(data);
        if (postgres) {
            if (cluster.public_url.empty()) {
                std::fprintf(stderr, "carrom-server: public_url_required: a PostgreSQL store "
                                     "runs in cluster mode: give --public-url ws://HOST:PORT "
                                     "(the address clients reach this instance at)\n");
                return 2;
            }
            if (cluster.instance_id.empty()) {
                cluster.instance_id = carrom::store::postgres::generate_instance_id();
            }
            cluster.lease = std::chrono::milliseconds(std::llround(lease_s * 1000.0));
            if (auto bad = carrom::store::postgres::check_cluster_options(cluster)) {
                std::fprintf(stderr, "carrom-server: %s: %s\n", bad->code.c_str(),
                             bad->message.c_str());
                return 2;
            }
        }
        auto opened = carrom::store::open_match_store(data, std::move(options),
                                                      postgres ? &cluster : nullptr);
        if (!opened.store) {
            std::fprintf(stderr, "carrom-server: %s: %s\n", opened.error->code.c_str(),
                         opened.error->message.c_str());
            return 2;
        }
        store = std::move(opened.store);
        spdlog::info("match store: {} ({})", opened.shown, store->health().backend);
        if (postgres) {
            spdlog::info("cluster: instance {} at {} (lease {} s)", cluster.instance_id,
                         cluster.public_url, lease_s);
        }
    } else {
        spdlog::info("no match store: matches end with the process (--data none)");
    }
    try {
        carrom::server::Server server(s,
                                      no_bots
                                          ? carrom::server::BotFactory{}
                                          : carrom::server::make_strategy_bot_factory(
                                                bot_seed, std::chrono::milliseconds(bot_think_ms)),
                                      web, store);
        std::uint16_t port = 0;
        try {
            port = server.listen();
        } catch (const carrom::server::TlsFileError& e) {
            std::fprintf(stderr, "carrom-server: bad_tls_files: %s\n", e.what());
            return 2;
        }
        std::printf("listening on %s:%u\n", s.host.c_str(), static_cast<unsigned>(port));
        std::fflush(stdout);
        spdlog::info("carrom-server on {}:{} ({} threads, {} Hz snapshots{})", s.host, port,
                     s.threads, s.snapshot_hz,
                     s.contact_snapshots ? " plus one per change of motion" : "");
        if (!s.tls_cert.empty()) {
            spdlog::info("TLS: https and wss on port {} (plain http and ws too)", port);
        }
        if (web) {
            spdlog::info("web client at http{}://{}:{}/ ({}: {} files, {} bytes)",
                         s.tls_cert.empty() ? "" : "s", s.host, port,
                         web_root.empty() ? "embedded" : web_root, web->file_count(),
                         web->total_bytes());
        } else {
            spdlog::info("web client off (--no-web)");
        }
        server.start();
        server.run_until_signal();
        spdlog::info("stopped");
    } catch (const std::exception& e) {
        spdlog::error("{}", e.what());
        return 1;
    }
    return 0;
}
