// Server: the listener, the I/O threads, signals and shutdown around the shared ServerCore.
#include "carrom/server/server.hpp"

#include "client_address.hpp"
#include "listener.hpp"
#include "room_actor.hpp"
#include "server_core.hpp"
#include "tls_context.hpp"
#include "ws_session.hpp"

#include "store/cluster.hpp"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/signal_set.hpp>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <future>
#include <optional>
#include <stdexcept>
#include <thread>
#include <unordered_map>
#include <vector>

namespace carrom::server {

struct Server::Impl {
    Impl(ServerSettings settings, BotFactory bots, std::shared_ptr<const StaticSite> web,
         std::shared_ptr<store::MatchStore> store)
        : core(std::move(settings), std::move(bots), std::move(web), std::move(store)) {}

    ServerCore core;
    std::shared_ptr<Listener> listener;
    std::vector<std::thread> threads;
    std::optional<asio::executor_work_guard<asio::io_context::executor_type>> work;
    bool stopped = false;
};

Server::Server(ServerSettings settings, BotFactory bots, std::shared_ptr<const StaticSite> web,
               std::shared_ptr<store::MatchStore> store)
    : impl_(std::make_unique<Impl>(std::move(settings), std::move(bots), std::move(web),
                                   std::move(store))) {}

Server::~Server() {
    shutdown();
}

std::uint16_t Server::listen() {
    auto& core = impl_->core;
    if (!core.settings.tls_cert.empty() || !core.settings.tls_key.empty()) {
        auto loaded = TlsContext::load(core.settings.tls_cert, core.settings.tls_key);
        if (auto* error = std::get_if<std::string>(&loaded)) {
            throw TlsFileError(*error);
        }
        core.tls = std::get<std::shared_ptr<TlsContext>>(std::move(loaded));
    }
    try {
        const auto address = asio::ip::make_address(core.settings.host);
        impl_->listener =
            std::make_shared<Listener>(core, tcp::endpoint(address, core.settings.port));
    } catch (const std::exception& e) {
        throw std::runtime_error("cannot listen on " + core.settings.host + ":" +
                                 std::to_string(core.settings.port) + ": " + e.what());
    }
    impl_->listener->run();
    return impl_->listener->port();
}

void Server::start() {
    if (impl_->core.store) {
        // Before the I/O threads run: no hello can come before the recovered rooms exist.
        const int recovered = impl_->core.restore_matches();
        spdlog::info("recovered {} matches", recovered);
        impl_->core.load_identities();
        if (store::Cluster* cluster = impl_->core.store->cluster()) {
            // Lease renewals, ownership checks and takeovers, on the cluster's own thread.
            auto& core = impl_->core;
            cluster->start(store::ClusterHandlers{
                [&core](std::vector<store::RecoveredMatch> matches) {
                    core.take_over(std::move(matches));
                },
                // Also from the store's writer thread, which may outlive the server: through the
                // gate that Server::shutdown closes.
                [&core, gate = core.confirmations](const store::MatchId& match,
                                                   const std::string& room_code) {
                    gate->pass([&] { core.match_lost(match, room_code); });
                },
                // On the directory's thread, which Server::shutdown stops first.
                [&core](std::vector<store::QuickPairing> pairings) {
                    core.quick_paired(std::move(pairings));
                },
                [&core](std::vector<store::WaitingRoom> rooms) {
                    core.open_handed_rooms(std::move(rooms));
                }});
        }
    }
    impl_->work.emplace(impl_->core.ioc.get_executor());
    const int count = std::max(1, impl_->core.settings.threads);
    for (int i = 0; i < count; ++i) {
        impl_->threads.emplace_back([this] { impl_->core.ioc.run(); });
    }
}

namespace {

using UrlByRoom = std::unordered_map<std::string, std::string>;

// Cluster mode, SIGTERM (docs/cluster.md, "Draining"): every room stops taking anything, the
// store writes what they journaled, and their unfinished matches go to the other live instances.
// The room codes handed over, with the URL of the instance that runs each now; null when nothing
// was handed over (no live instance, or the database does not answer: the matches are claimed as
// orphans once the lease ends).
std::shared_ptr<const UrlByRoom> drain(ServerCore& core) {
    std::vector<std::future<std::optional<store::WaitingRoom>>> frozen;
    core.registry.for_each_room(
        [&](const std::shared_ptr<RoomActor>& room) { frozen.push_back(room->freeze()); });
    std::vector<store::WaitingRoom> waiting; // rooms waiting for their players go along
    for (auto& f : frozen) {
        if (f.wait_for(std::chrono::seconds(2)) == std::future_status::ready) {
            if (auto room = f.get()) {
                waiting.push_back(std::move(*room));
            }
        }
    }
    if (!core.store->flush(std::chrono::seconds(5))) {
        spdlog::error("drain: the match store did not write everything; no match handed over");
        return nullptr;
    }
    auto handed = core.cluster()->hand_over(std::move(waiting));
    if (!handed.ok()) {
        spdlog::error("drain: no match handed over: {}", handed.error->message);
        return nullptr;
    }
    if (handed.value.empty()) {
        return nullptr;
    }
    auto urls = std::make_shared<UrlByRoom>();
    for (const auto& match : handed.value) {
        (*urls)[match.room_code] = match.public_url;
    }
    const auto rooms = static_cast<std::size_t>(
        std::count_if(handed.value.begin(), handed.value.end(),
                      [](const store::HandedMatch& h) { return h.match.empty(); }));
    spdlog::info("drain: {} matches handed over, and {} rooms waiting for their players",
                 handed.value.size() - rooms, rooms);
    return urls;
}

} // namespace

void Server::shutdown() {
    if (impl_->stopped) {
        return;
    }
    impl_->stopped = true;
    auto& core = impl_->core;
    core.stopping = true;
    if (core.store && core.store->cluster()) {
        core.store->cluster()->stop(); // no takeover from now on
    }
    if (impl_->listener) {
        impl_->listener->stop();
    }
    std::shared_ptr<const UrlByRoom> moved;
    if (core.cluster() != nullptr && !impl_->threads.empty()) {
        moved = drain(core);
    } else if (!impl_->threads.empty()) {
        // What the rooms are sending (a joiner's room_state) goes out before shutting_down.
        std::vector<std::future<void>> settled;
        core.registry.for_each_room(
            [&](const std::shared_ptr<RoomActor>& room) { settled.push_back(room->settled()); });
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(1);
        for (auto& f : settled) {
            (void)f.wait_until(until);
        }
    }
    std::vector<std::shared_ptr<WsSession>> sessions;
    {
        std::lock_guard lock(core.sessions_mutex);
        for (auto& [ptr, weak] : core.sessions) {
            if (auto s = weak.lock()) {
                sessions.push_back(std::move(s));
            }
        }
    }
    for (auto& s : sessions) {
        if (moved) {
            s->move_or_shutdown(moved);
        } else {
            s->shutdown();
        }
    }
    sessions.clear();
    const auto deadline =
        std::chrono::steady_clock::now() + to_duration(core.settings.shutdown_grace_s);
    while (!impl_->threads.empty() && core.metrics.connections.load() > 0 &&
           std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    core.registry.for_each_room([](const std::shared_ptr<RoomActor>& room) { room->stop(); });
    impl_->work.reset();
    core.ioc.stop();
    for (auto& t : impl_->threads) {
        t.join();
    }
    impl_->threads.clear();
    {
        std::lock_guard lock(core.sessions_mutex);
        for (auto& [ptr, weak] : core.sessions) {
            if (auto s = weak.lock()) {
                s->release_room(); // no thread runs the sessions any more
            }
        }
    }
    // No store confirmation reaches a room or ioc from now on: the store may outlive both.
    core.confirmations->close();
    if (core.match_reader) {
        core.match_reader->stop(); // no answer posts to a session after this
    }
    core.bot_pool.join();
    if (core.store) {
        // Everything the rooms journaled, written before the process ends (their unfinished
        // matches stay unfinished: core.stopping keeps them from being marked abandoned).
        const auto timeout = std::chrono::seconds(5);
        if (core.store->flush(timeout)) {
            spdlog::info("match store flushed");
        } else {
            const auto health = core.store->health();
            spdlog::error("match store: {} items not written within {} s ({})", health.pending,
                          timeout.count(), health.last_error);
        }
    }
}

std::string tls_files_problem(const ServerSettings& settings) {
    if (settings.tls_cert.empty() && settings.tls_key.empty()) {
        return {};
    }
    auto loaded = TlsContext::load(settings.tls_cert, settings.tls_key);
    auto* error = std::get_if<std::string>(&loaded);
    return error != nullptr ? *error : std::string();
}

std::string trusted_proxies_problem(const ServerSettings& settings) {
    return trusted_proxies_problem(settings.trusted_proxies);
}

bool Server::reload_tls(std::string& result) {
    if (!impl_->core.tls) {
        result = "no TLS certificate to reload (no --tls-cert)";
        return false;
    }
    const auto reloaded = impl_->core.tls->reload();
    result = reloaded.text;
    return reloaded.ok;
}

void Server::run_until_signal() {
    asio::io_context signal_ioc;
    asio::signal_set signals(signal_ioc, SIGINT, SIGTERM, SIGHUP);
    std::function<void(const boost::system::error_code&, int)> on_signal =
        [&](const boost::system::error_code& ec, int signal) {
            if (ec) {
                return;
            }
            if (signal != SIGHUP) {
                spdlog::info("signal {}: shutting down", signal);
                return; // signal_ioc.run() returns
            }
            std::string result;
            if (reload_tls(result)) {
                spdlog::info("SIGHUP: {}", result);
            } else {
                spdlog::warn("SIGHUP: {}", result);
            }
            signals.async_wait(on_signal);
        };
    signals.async_wait(on_signal);
    signal_ioc.run();
    shutdown();
}

const Metrics& Server::metrics() const {
    return impl_->core.metrics;
}
const ServerSettings& Server::settings() const {
    return impl_->core.settings;
}

} // namespace carrom::server
