// The match API through a real Server in process, with a real SQLite store in a temporary
// directory and real sockets: reads run on the reader thread (a read held by the store's test
// seam stops neither a match nor /healthz on the server's one I/O thread), 503 store_busy once
// 64 reads wait, 429 rate_limited per client address with Retry-After; and a store that outlives
// its server (as in carrom-server's main) confirming writes while and after the server goes.
#include "server/socket_fixture.hpp"
#include "store/sqlite_match_store.hpp"
#include "support/temp_dir.hpp"

#include <boost/asio/connect.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/read.hpp>
#include <boost/asio/write.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <poll.h>

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace carrom::server {
namespace {

using namespace std::chrono_literals;
using testing::kUp;
using testing::WsTestClient;
namespace asio = boost::asio;

// Holds the calls of a test seam while closed; counts the calls held.
class Latch {
public:
    void close() {
        const std::lock_guard lock(mutex_);
        closed_ = true;
    }
    void open() {
        {
            const std::lock_guard lock(mutex_);
            closed_ = false;
        }
        cv_.notify_all();
    }
    void pass() {
        std::unique_lock lock(mutex_);
        ++held_;
        cv_.notify_all();
        cv_.wait(lock, [&] { return !closed_; });
        --held_;
    }
    bool wait_held(int count, std::chrono::milliseconds timeout) {
        std::unique_lock lock(mutex_);
        return cv_.wait_for(lock, timeout, [&] { return held_ >= count; });
    }

private:
    std::mutex mutex_;
    std::condition_variable cv_;
    bool closed_ = false;
    int held_ = 0;
};

struct Answer {
    int status = 0;
    std::string retry_after;
    std::string body;
    std::string code() const {
        const auto json = nlohmann::json::parse(body, nullptr, false);
        return json.is_object() && json.contains("error") ? json["error"].value("code", "") : "";
    }
};

// One HTTP/1.1 GET on its own connection (from the local address `from`), answered later.
class PendingGet {
public:
    PendingGet(std::uint16_t port, const std::string& target, const std::string& from = "127.0.0.1")
        : socket_(ioc_) {
        socket_.open(asio::ip::tcp::v4());
        socket_.bind({asio::ip::make_address(from), 0});
        socket_.connect({asio::ip::make_address("127.0.0.1"), port});
        const std::string request =
            "GET " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n";
        asio::write(socket_, asio::buffer(request));
    }
    // The answer, or nothing when none starts within wait.
    std::optional<Answer> answer(std::chrono::milliseconds wait) {
        pollfd fd{socket_.native_handle(), POLLIN, 0};
        if (::poll(&fd, 1, static_cast<int>(wait.count())) <= 0) {
            return std::nullopt;
        }
        std::string bytes;
        boost::system::error_code ec;
        asio::read(socket_, asio::dynamic_buffer(bytes), ec); // to the end: the server closes
        Answer out;
        if (bytes.size() < 12) {
            return out;
        }
        out.status = std::stoi(bytes.substr(9, 3));
        const auto end = bytes.find("\r\n\r\n");
        const std::string head = bytes.substr(0, end);
        out.body = end == std::string::npos ? "" : bytes.substr(end + 4);
        const std::string field = "\r\nRetry-After: ";
        if (const auto at = head.find(field); at != std::string::npos) {
            const auto from = at + field.size();
            out.retry_after = head.substr(from, head.find("\r\n", from) - from);
        }
        return out;
    }

private:
    asio::io_context ioc_;
    asio::ip::tcp::socket socket_;
};

class MatchApiServerTest : public ::testing::Test {
protected:
    void start(ServerSettings settings, store::SqliteStoreOptions options = {}) {
        options.before_read = [this] { reads_.pass(); };
        auto opened = store::SqliteMatchStore::open(dir_.file("c.db"), std::move(options));
        ASSERT_FALSE(opened.error) << opened.error->message;
        store_ = std::move(opened.store);
        server_ = std::make_unique<Server>(settings, BotFactory{}, nullptr, store_);
        port_ = server_->listen();
        server_->start();
    }
    void TearDown() override {
        reads_.open();
        server_.reset();
        store_.reset();
    }
    Answer get(const std::string& target, const std::string& from = "127.0.0.1") {
        return PendingGet(port_, target, from).answer(10s).value_or(Answer{});
    }
    std::unique_ptr<WsTestClient> connect(const std::string& name) {
        auto client = std::make_unique<WsTestClient>(port_);
        client->send(proto::Hello{proto::kProtocolVersion, name, std::nullopt});
        EXPECT_TRUE(client->wait_for<proto::Welcome>());
        return client;
    }
    // A and B seated in an icf room.
    void seat(WsTestClient& a, WsTestClient& b) {
        a.send(proto::CreateRoom{});
        const auto created = a.wait_for<proto::RoomState>();
        ASSERT_TRUE(created);
        b.send(proto::JoinRoom{created->code, proto::Role::Player});
        ASSERT_TRUE(b.wait_for<proto::RoomState>());
        ASSERT_TRUE(a.wait_for_event<proto::TurnEvent>());
        ASSERT_TRUE(b.wait_for_event<proto::TurnEvent>());
    }

    test_support::TempDir dir_{"carrom_match_api_server"};
    Latch reads_;
    std::shared_ptr<store::SqliteMatchStore> store_;
    std::unique_ptr<Server> server_;
    std::uint16_t port_ = 0;
};

ServerSettings one_thread() {
    ServerSettings s = testing::test_settings();
    s.threads = 1; // a read on the I/O thread would stop everything else
    s.http_rate = 1000.0;
    s.http_burst = 1000.0;
    return s;
}

TEST_F(MatchApiServerTest, AHeldReadStopsNeitherAMatchNorHealthzOnTheOneIoThread) {
    ServerSettings settings = one_thread();
    settings.handshake_timeout_s = 1.0; // the read is held longer: its answer still goes out
    start(settings);
    reads_.close();
    PendingGet read(port_, "/matches?player=Asha");
    ASSERT_TRUE(reads_.wait_held(1, 5s)); // the read is in the store, held

    EXPECT_EQ(get("/healthz").body, "ok\n");
    auto a = connect("Asha");
    auto b = connect("Bo");
    seat(*a, *b);
    a->send(proto::Shoot{0, 300.0, kUp, 9.0});
    ASSERT_TRUE(b->wait_for<proto::ShotResult>(15000ms));
    EXPECT_GT(b->logged<proto::Snapshot>().size(), 10U); // the stroke streamed
    EXPECT_FALSE(read.answer(0ms));                      // while the read still waits
    std::this_thread::sleep_for(1100ms);                 // past the request's timeout

    reads_.open();
    const auto answer = read.answer(5000ms);
    ASSERT_TRUE(answer);
    EXPECT_EQ(answer->status, 200) << answer->body;
    EXPECT_EQ(nlohmann::json::parse(answer->body)["matches"].size(), 1U);
}

TEST_F(MatchApiServerTest, SixtyFourReadsWaitTheNextIs503StoreBusy) {
    start(one_thread());
    reads_.close();
    std::vector<std::unique_ptr<PendingGet>> gets;
    gets.push_back(std::make_unique<PendingGet>(port_, "/matches/first"));
    ASSERT_TRUE(reads_.wait_held(1, 5s)); // the reader holds one; the queue is empty
    for (int i = 0; i < 65; ++i) {        // 64 queue, one is refused
        gets.push_back(std::make_unique<PendingGet>(port_, "/matches/m" + std::to_string(i)));
    }
    std::vector<Answer> busy;
    const auto deadline = std::chrono::steady_clock::now() + 5s;
    while (busy.empty() && std::chrono::steady_clock::now() < deadline) {
        for (auto& g : gets) {
            if (g) {
                if (auto answer = g->answer(0ms)) {
                    busy.push_back(*answer);
                    g.reset();
                }
            }
        }
        std::this_thread::sleep_for(5ms);
    }
    ASSERT_EQ(busy.size(), 1U);
    EXPECT_EQ(busy[0].status, 503);
    EXPECT_EQ(busy[0].code(), "store_busy");
    reads_.open();
    int answered = 0;
    for (auto& g : gets) {
        if (g) {
            const auto answer = g->answer(5000ms);
            ASSERT_TRUE(answer);
            EXPECT_EQ(answer->status, 404) << answer->body; // read: no such match
            EXPECT_EQ(answer->code(), "unknown_match");
            ++answered;
        }
    }
    EXPECT_EQ(answered, 65);
}

TEST_F(MatchApiServerTest, ABurstFromOneAddressIs429WithRetryAfterOthersGoOn) {
    ServerSettings settings = testing::test_settings();
    settings.http_rate = 1.0;
    settings.http_burst = 3.0;
    start(settings);
    for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(get("/matches/abc").status, 404) << i;
    }
    const Answer limited = get("/matches?player=Asha");
    EXPECT_EQ(limited.status, 429);
    EXPECT_EQ(limited.code(), "rate_limited");
    EXPECT_EQ(limited.retry_after, "1");
    EXPECT_NE(nlohmann::json::parse(limited.body)["error"]["message"].get<std::string>().find(
                  "retry in 1 s"),
              std::string::npos)
        << limited.body;
    EXPECT_EQ(get("/metrics").status, 429);                  // the same budget
    EXPECT_EQ(get("/healthz").body, "ok\n");                 // never limited (health probes)
    EXPECT_EQ(get("/matches/abc", "127.0.0.2").status, 404); // another address: its own budget

    std::this_thread::sleep_for(1100ms); // Retry-After
    const Answer metrics = get("/metrics");
    EXPECT_EQ(metrics.status, 200);
    EXPECT_NE(metrics.body.find("carrom_http_rate_limited_total 2\n"), std::string::npos)
        << metrics.body;
}

// carrom-server's main keeps its own reference to the store: the store outlives the server and
// confirms writes held back while the server shuts down and is destroyed (ASan: nothing touches
// the rooms or the io_context after they are gone).
TEST_F(MatchApiServerTest, AStoreThatOutlivesItsServerConfirmsWritesSafely) {
    Latch writes;
    store::SqliteStoreOptions options;
    options.fail_writes = [&writes] {
        writes.pass();
        return false;
    };
    ServerSettings settings = testing::test_settings();
    settings.shutdown_grace_s = 0.2;
    start(settings, std::move(options));
    std::vector<std::unique_ptr<WsTestClient>> clients;
    constexpr int kRooms = 6;
    for (int i = 0; i < kRooms; ++i) {
        clients.push_back(connect("A" + std::to_string(i)));
        clients.push_back(connect("B" + std::to_string(i)));
        seat(*clients[clients.size() - 2], *clients.back());
    }
    ASSERT_TRUE(store_->flush(5s));
    writes.close(); // the next transaction waits before its COMMIT
    for (int i = 0; i < kRooms; ++i) {
        clients[static_cast<std::size_t>(2 * i)]->send(proto::Shoot{0, 300.0, kUp, 9.0});
    }
    ASSERT_TRUE(writes.wait_held(1, 5s));
    std::this_thread::sleep_for(100ms); // the other strokes queue behind the held transaction
    EXPECT_FALSE(clients[1]->wait_for<proto::ShotResult>(200ms)); // unconfirmed: not streamed
    std::atomic<bool> released{false};
    std::thread release([&] {
        std::this_thread::sleep_for(5200ms); // past the shutdown's 5 s flush
        writes.open();
        released = true;
    });
    server_.reset(); // the flush times out; the confirmations come while the core goes
    release.join();
    EXPECT_TRUE(released);
    EXPECT_TRUE(store_->flush(5s));
    EXPECT_GE(store_->health().written_total, static_cast<std::uint64_t>(kRooms));
    store_.reset();
}

} // namespace
} // namespace carrom::server
