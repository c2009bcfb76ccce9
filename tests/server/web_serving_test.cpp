// carrom-server serving the web client: the real program on 127.0.0.1 with an ephemeral port,
// spoken to over raw TCP sockets with exactly the bytes each test wants. Every refusal is
// followed by a request that must still be served.
#include "carrom/proto/client_messages.hpp"
#include "carrom/proto/server_messages.hpp"
#include "server/ws_test_client.hpp"
#include "support/child_process.hpp"
#include "support/read_file.hpp"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace carrom::server {
namespace {

using namespace std::chrono_literals;
using test_support::ChildProcess;
using Clock = std::chrono::steady_clock;
using test_support::read_file;

struct HttpAnswer {
    int status = 0;
    std::map<std::string, std::string> headers; // names in lower case
    std::string body;
    bool has(const std::string& name) const { return headers.count(name) > 0; }
    std::string header(const std::string& name) const {
        const auto it = headers.find(name);
        return it == headers.end() ? std::string() : it->second;
    }
};

// Splits what a connection received into answers. A HEAD's and a 304's have no body whatever
// their Content-Length says (`no_body`: the request was HEAD).
std::vector<HttpAnswer> parse_answers(std::string bytes, bool no_body = false) {
    std::vector<HttpAnswer> out;
    while (!bytes.empty()) {
        const std::size_t end = bytes.find("\r\n\r\n");
        if (end == std::string::npos) {
            ADD_FAILURE() << "an incomplete answer: " << bytes;
            break;
        }
        HttpAnswer a;
        std::istringstream head(bytes.substr(0, end));
        std::string line;
        std::getline(head, line);
        if (line.rfind("HTTP/1.1 ", 0) == 0 && line.size() >= 12) {
            a.status = std::stoi(line.substr(9, 3));
        }
        while (std::getline(head, line)) {
            if (!line.empty() && line.back() == '\r') {
                line.pop_back();
            }
            const std::size_t colon = line.find(':');
            if (colon == std::string::npos) {
                continue;
            }
            std::string name = line.substr(0, colon);
            std::transform(name.begin(), name.end(), name.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            std::string value = line.substr(colon + 1);
            value.erase(0, value.find_first_not_of(' '));
            a.headers[name] = value;
        }
        bytes.erase(0, end + 4);
        std::size_t length = 0;
        if (!no_body && a.status != 304 && a.has("content-length")) {
            length = std::stoul(a.header("content-length"));
        }
        a.body = bytes.substr(0, length);
        bytes.erase(0, std::min(length, bytes.size()));
        out.push_back(std::move(a));
    }
    return out;
}

// Sends `request` on a new connection and reads until the server closes it (or 10 s pass).
std::string send_and_read(std::uint16_t port, const std::string& request) {
    const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(port);
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (::connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address) != 0) {
        ::close(fd);
        ADD_FAILURE() << "cannot connect to port " << port;
        return {};
    }
    std::size_t sent = 0;
    while (sent < request.size()) {
        const ssize_t n = ::send(fd, request.data() + sent, request.size() - sent, MSG_NOSIGNAL);
        if (n <= 0) {
            break; // the server may answer and close before it has read everything
        }
        sent += static_cast<std::size_t>(n);
    }
    std::string received;
    const auto deadline = Clock::now() + 10s;
    while (Clock::now() < deadline) {
        pollfd p{fd, POLLIN, 0};
        if (::poll(&p, 1, 200) <= 0) {
            continue;
        }
        char buffer[16384];
        const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
        if (n <= 0) {
            break;
        }
        received.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(fd);
    return received;
}

std::string request_text(const std::string& method, const std::string& target,
                         const std::string& extra_headers = "") {
    return method + " " + target + " HTTP/1.1\r\nHost: 127.0.0.1\r\n" + extra_headers +
           "Connection: close\r\n\r\n";
}

// The one answer to one request on its own connection.
HttpAnswer ask(std::uint16_t port, const std::string& method, const std::string& target,
               const std::string& extra_headers = "") {
    const auto answers = parse_answers(
        send_and_read(port, request_text(method, target, extra_headers)), method == "HEAD");
    if (answers.size() != 1) {
        ADD_FAILURE() << answers.size() << " answers to " << method << " " << target;
        return {};
    }
    return answers.front();
}

HttpAnswer ask_raw(std::uint16_t port, const std::string& bytes) {
    const auto answers = parse_answers(send_and_read(port, bytes));
    if (answers.size() != 1) {
        ADD_FAILURE() << answers.size() << " answers to " << bytes.substr(0, 80);
        return {};
    }
    return answers.front();
}

std::filesystem::path web_dir() {
    const char* source = std::getenv("CARROM_SOURCE_DIR");
    return std::filesystem::path(source != nullptr ? source : ".") / "web";
}

class ServerProcess {
public:
    explicit ServerProcess(const std::vector<std::string>& flags = {}) {
        std::vector<std::string> argv{CARROM_SERVER_PATH, "--host", "127.0.0.1", "--port", "0",
                                      "--log-level",      "warn",   "--data",    "none"};
        argv.insert(argv.end(), flags.begin(), flags.end());
        process_ = std::make_unique<ChildProcess>(argv);
        const std::string prefix = "listening on 127.0.0.1:";
        const auto line =
            process_->wait_line(ChildProcess::Stream::Out, prefix, Clock::now() + 15s);
        if (line) {
            port_ = static_cast<std::uint16_t>(std::stoi(line->substr(prefix.size())));
        }
    }
    std::uint16_t port() const { return port_; }
    ChildProcess& process() { return *process_; }

    // The server still answers /healthz and the page after whatever came before.
    void expect_serving() const {
        const HttpAnswer health = ask(port_, "GET", "/healthz");
        EXPECT_EQ(health.status, 200);
        EXPECT_EQ(health.body, "ok\n");
    }

private:
    std::unique_ptr<ChildProcess> process_;
    std::uint16_t port_ = 0;
};

class WebServing : public ::testing::Test {
protected:
    void SetUp() override { ASSERT_NE(server_.port(), 0) << "carrom-server did not start"; }
    std::uint16_t port() const { return server_.port(); }
    void expect_serving() const {
        server_.expect_serving();
        EXPECT_EQ(ask(port(), "GET", "/").status, 200);
    }

    ServerProcess server_;
};

TEST_F(WebServing, ServesTheEmbeddedPageWithTypeEtagAndCaching) {
    ASSERT_NE(std::getenv("CARROM_SOURCE_DIR"), nullptr) << "CARROM_SOURCE_DIR is set by ctest";
    const std::string index = read_file(web_dir() / "index.html");
    ASSERT_FALSE(index.empty());
    const HttpAnswer root = ask(port(), "GET", "/");
    EXPECT_EQ(root.status, 200);
    EXPECT_EQ(root.header("content-type"), "text/html; charset=utf-8");
    EXPECT_EQ(root.header("cache-control"), "no-cache");
    EXPECT_EQ(root.header("x-content-type-options"), "nosniff");
    EXPECT_NE(root.header("content-security-policy").find("default-src 'self'"), std::string::npos);
    EXPECT_EQ(root.header("content-length"), std::to_string(index.size()));
    EXPECT_EQ(root.body, index);
    ASSERT_GE(root.header("etag").size(), 3u);
    EXPECT_EQ(root.header("etag").front(), '"');

    const HttpAnswer named = ask(port(), "GET", "/index.html?ws=ws://127.0.0.1:1/");
    EXPECT_EQ(named.status, 200);
    EXPECT_EQ(named.body, index);
    EXPECT_EQ(named.header("etag"), root.header("etag"));

    const std::pair<const char*, const char*> files[] = {
        {"/js/app.js", "text/javascript; charset=utf-8"},
        {"/style.css", "text/css; charset=utf-8"},
        {"/favicon.svg", "image/svg+xml"}};
    for (const auto& [target, type] : files) {
        const HttpAnswer file = ask(port(), "GET", target);
        EXPECT_EQ(file.status, 200) << target;
        EXPECT_EQ(file.header("content-type"), type) << target;
        EXPECT_EQ(file.body, read_file(web_dir() / std::string(target).substr(1))) << target;
    }
}

#ifdef CARROM_WEB_WASM_PATH
// The engine emscripten built (wasm/CMakeLists.txt) is embedded and served as WebAssembly, which
// the page's policy lets it compile.
TEST_F(WebServing, ServesTheEngineAsWebAssembly) {
    const HttpAnswer engine = ask(port(), "GET", "/js/carrom_engine.wasm");
    EXPECT_EQ(engine.status, 200);
    EXPECT_EQ(engine.header("content-type"), "application/wasm");
    EXPECT_EQ(engine.header("cache-control"), "no-cache");
    EXPECT_EQ(engine.body, read_file(CARROM_WEB_WASM_PATH));
    EXPECT_EQ(engine.body.substr(0, 4), std::string("\0asm", 4));
    const HttpAnswer page = ask(port(), "GET", "/");
    EXPECT_NE(page.header("content-security-policy").find("script-src 'self' 'wasm-unsafe-eval';"),
              std::string::npos);
}
#endif

TEST_F(WebServing, IfNoneMatchWithTheEtagIsNotModified) {
    const HttpAnswer first = ask(port(), "GET", "/js/app.js");
    ASSERT_EQ(first.status, 200);
    const std::string etag = first.header("etag");
    const HttpAnswer again = ask(port(), "GET", "/js/app.js", "If-None-Match: " + etag + "\r\n");
    EXPECT_EQ(again.status, 304);
    EXPECT_EQ(again.header("etag"), etag);
    EXPECT_EQ(again.header("cache-control"), "no-cache");
    EXPECT_TRUE(again.body.empty());
    const HttpAnswer other = ask(port(), "GET", "/js/app.js", "If-None-Match: \"0\"\r\n");
    EXPECT_EQ(other.status, 200);
    EXPECT_EQ(other.body, first.body);
    expect_serving();
}

TEST_F(WebServing, HeadHasTheHeadersAndNoBody) {
    const HttpAnswer get = ask(port(), "GET", "/");
    const std::string bytes = send_and_read(port(), request_text("HEAD", "/"));
    const auto head = parse_answers(bytes, true);
    ASSERT_EQ(head.size(), 1u);
    EXPECT_EQ(head[0].status, 200);
    EXPECT_EQ(head[0].header("content-length"), std::to_string(get.body.size()));
    EXPECT_EQ(head[0].header("etag"), get.header("etag"));
    EXPECT_EQ(head[0].header("content-type"), "text/html; charset=utf-8");
    // Nothing at all after the header block.
    EXPECT_EQ(bytes.size(), bytes.find("\r\n\r\n") + 4);
    expect_serving();
}

TEST_F(WebServing, TraversalAndBadTargetsAreRefused) {
    const std::pair<const char*, int> cases[] = {
        {"/../", 400},
        {"/../../etc/passwd", 400},
        {"/js/../index.html", 400},
        {"/./index.html", 400},
        {"/%2e%2e/", 400},
        {"/%2e%2e/%2e%2e/etc/passwd", 400},
        {"/%2E%2E%2Fetc%2Fpasswd", 400},
        {"/%2f", 400},
        {"/js%2fapp.js", 400},
        {"/%5c..%5cindex.html", 400},
        {"/index.html%00", 400},
        {"/index.html%00.png", 400},
        {"/%zz", 400},
        {"//etc/passwd", 400},
        {"http://127.0.0.1/index.html", 400},
        {"/etc/passwd", 404},
        {"/.git/config", 404},
        {"/%2egit/config", 404},
        {"/no-such-file.js", 404},
    };
    for (const auto& [target, status] : cases) {
        const HttpAnswer a = ask(port(), "GET", target);
        EXPECT_EQ(a.status, status) << target;
        EXPECT_EQ(a.header("cache-control"), "no-store") << target;
        EXPECT_EQ(a.header("content-type"), "text/plain; charset=utf-8") << target;
        EXPECT_EQ(a.body.find("root:"), std::string::npos) << target;
    }
    // A raw NUL byte in the request line never reaches the site: the request is malformed.
    const HttpAnswer nul =
        ask_raw(port(), std::string("GET /index.html\0.png HTTP/1.1\r\nHost: x\r\n\r\n", 42));
    EXPECT_EQ(nul.status, 400);
    expect_serving();
}

TEST_F(WebServing, OverlongTargetsAndHeadersAreRefused) {
    // Within the request size the server reads: the site's limit of 2,048 bytes.
    EXPECT_EQ(ask(port(), "GET", "/" + std::string(3000, 'a')).status, 414);
    EXPECT_EQ(
        ask(port(), "GET", "/", "If-None-Match: \"" + std::string(3000, 'a') + "\"\r\n").status,
        431);
    // Beyond it (8 KiB of request line and headers).
    EXPECT_EQ(ask(port(), "GET", "/" + std::string(20000, 'a')).status, 414);
    EXPECT_EQ(ask(port(), "GET", "/", "X-Long: " + std::string(20000, 'b') + "\r\n").status, 431);
    std::string many;
    for (int i = 0; i < 1000; ++i) {
        many += "X-H" + std::to_string(i) + ": v\r\n";
    }
    EXPECT_EQ(ask(port(), "GET", "/", many).status, 431);
    expect_serving();
}

TEST_F(WebServing, MethodsOtherThanGetAndHeadAreNotAllowed) {
    for (const char* method : {"POST", "PUT", "DELETE", "PATCH", "OPTIONS", "get"}) {
        const HttpAnswer a = ask(port(), method, "/index.html");
        EXPECT_EQ(a.status, 405) << method;
        EXPECT_EQ(a.header("allow"), "GET, HEAD") << method;
    }
    const HttpAnswer put =
        ask_raw(port(), "PUT /index.html HTTP/1.1\r\nHost: x\r\nContent-Length: 11\r\n"
                        "Connection: close\r\n\r\nhello world");
    EXPECT_EQ(put.status, 405);
    const HttpAnswer large =
        ask_raw(port(), "POST / HTTP/1.1\r\nHost: x\r\nContent-Length: 5000\r\n\r\n" +
                            std::string(5000, 'x'));
    EXPECT_EQ(large.status, 413);
    const HttpAnswer health = ask(port(), "POST", "/healthz");
    EXPECT_EQ(health.status, 405);
    EXPECT_EQ(health.header("allow"), "GET");
    expect_serving();
}

TEST_F(WebServing, KeepsTheConnectionForTheNextFile) {
    const std::string bytes =
        send_and_read(port(), "GET / HTTP/1.1\r\nHost: x\r\n\r\n"
                              "GET /style.css HTTP/1.1\r\nHost: x\r\nConnection: close\r\n\r\n");
    const auto answers = parse_answers(bytes);
    ASSERT_EQ(answers.size(), 2u);
    EXPECT_EQ(answers[0].status, 200);
    EXPECT_NE(answers[0].header("connection"), "close");
    EXPECT_EQ(answers[1].status, 200);
    EXPECT_EQ(answers[1].header("content-type"), "text/css; charset=utf-8");
}

TEST_F(WebServing, TheWebSocketAndMetricsStillAnswer) {
    testing::WsTestClient client(port()); // upgrades at "/", the page's own address
    client.send(proto::Hello{proto::kProtocolVersion, "Asha", std::nullopt});
    EXPECT_TRUE(client.wait_for<proto::Welcome>());
    const HttpAnswer metrics = ask(port(), "GET", "/metrics");
    EXPECT_EQ(metrics.status, 200);
    EXPECT_NE(metrics.body.find("carrom_http_requests_total"), std::string::npos);
    expect_serving();
}

TEST(WebServingFlags, NoWebAnswersNotFound) {
    ServerProcess server({"--no-web"});
    ASSERT_NE(server.port(), 0);
    EXPECT_EQ(ask(server.port(), "GET", "/").status, 404);
    EXPECT_EQ(ask(server.port(), "GET", "/index.html").status, 404);
    EXPECT_EQ(ask(server.port(), "HEAD", "/js/app.js").status, 404);
    EXPECT_EQ(ask(server.port(), "POST", "/").status, 404);
    server.expect_serving();
}

TEST(WebServingFlags, WebRootServesThatDirectory) {
    namespace fs = std::filesystem;
    const fs::path root =
        fs::temp_directory_path() / ("carrom_web_root_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "js");
    std::ofstream(root / "index.html") << "<!doctype html><title>other</title>\n";
    std::ofstream(root / "js" / "main.js") << "export const x = 1;\n";
    std::ofstream(root / ".secret") << "hidden\n";
    std::error_code ec;
    fs::create_symlink("/etc/hostname", root / "linked.txt", ec);
    {
        ServerProcess server({"--web-root", root.string()});
        ASSERT_NE(server.port(), 0);
        const HttpAnswer index = ask(server.port(), "GET", "/");
        EXPECT_EQ(index.status, 200);
        EXPECT_EQ(index.body, "<!doctype html><title>other</title>\n");
        const HttpAnswer js = ask(server.port(), "GET", "/js/main.js");
        EXPECT_EQ(js.status, 200);
        EXPECT_EQ(js.header("content-type"), "text/javascript; charset=utf-8");
        EXPECT_EQ(js.body, "export const x = 1;\n");
        EXPECT_EQ(ask(server.port(), "GET", "/js/app.js").status, 404); // not the embedded copy
        EXPECT_EQ(ask(server.port(), "GET", "/.secret").status, 404);
        EXPECT_EQ(ask(server.port(), "GET", "/linked.txt").status, 404);
        server.expect_serving();
    }
    fs::remove_all(root);
}

TEST(WebServingFlags, ABadWebRootStopsTheStart) {
    namespace fs = std::filesystem;
    const fs::path empty =
        fs::temp_directory_path() / ("carrom_web_empty_" + std::to_string(::getpid()));
    fs::create_directories(empty);
    const std::pair<std::string, std::string> cases[] = {
        {"/no/such/dir", "carrom-server: bad_web_root: The web root /no/such/dir is not a "
                         "directory."},
        {empty.string(),
         "carrom-server: bad_web_root: The web root " + empty.string() + " has no index.html."}};
    for (const auto& [dir, sentence] : cases) {
        ChildProcess server({CARROM_SERVER_PATH, "--host", "127.0.0.1", "--port", "0", "--data",
                             "none", "--web-root", dir});
        EXPECT_EQ(server.wait_exit(Clock::now() + 15s), 2) << dir;
        EXPECT_TRUE(server.wait_line(ChildProcess::Stream::Err, sentence, Clock::now() + 1s))
            << dir;
        EXPECT_TRUE(server.lines(ChildProcess::Stream::Out).empty()) << "it never listened";
    }
    fs::remove_all(empty);
}

} // namespace
} // namespace carrom::server
