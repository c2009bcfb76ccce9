// StaticSite: target normalisation, statuses, headers and bodies of the web client's files, the
// directory loader and the files the build embeds.
#include "carrom/server/static_site.hpp"
#include "carrom/server/web_assets.hpp"
#include "support/read_file.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <unistd.h>

namespace carrom::server {
namespace {

using namespace std::string_literals;
using namespace std::string_view_literals;
namespace fs = std::filesystem;

constexpr EmbeddedFile kFiles[] = {
    {"index.html", "<!doctype html><title>t</title>"},
    {"js/app.js", "export const a = 1;\n"},
    {"js/index.html", "<p>js</p>"},
    {"style.css", "body{}"},
    {"a b.txt", "space"},
    {"caf\xc3\xa9.txt", "utf-8 name"},
    {"img/dot.png", "\x89PNG\r\n\x1a\n\0\0"sv},
    {"data", "no extension"},
};

const StaticSite& site() {
    static const StaticSite s = StaticSite::from_files(kFiles);
    return s;
}

StaticResponse get(std::string_view target, std::string_view method = "GET") {
    return site().respond({method, target, std::nullopt});
}

std::string path_of(std::string_view target) {
    const auto r = resolve_target(target);
    return std::holds_alternative<std::string>(r) ? std::get<std::string>(r) : "";
}

int status_of(std::string_view target) {
    const auto r = resolve_target(target);
    return std::holds_alternative<int>(r) ? std::get<int>(r) : 0;
}

// --- resolve_target: what a target names -------------------------------------------------------

TEST(ResolveTarget, RootIsTheIndex) {
    EXPECT_EQ(path_of("/"), "index.html");
}

TEST(ResolveTarget, PlainFile) {
    EXPECT_EQ(path_of("/index.html"), "index.html");
}

TEST(ResolveTarget, NestedFile) {
    EXPECT_EQ(path_of("/js/app.js"), "js/app.js");
}

TEST(ResolveTarget, DirectoryWithSlashIsItsIndex) {
    EXPECT_EQ(path_of("/js/"), "js/index.html");
}

TEST(ResolveTarget, QueryIsIgnored) {
    EXPECT_EQ(path_of("/js/app.js?v=2&x=/../y"), "js/app.js");
    EXPECT_EQ(path_of("/?ws=ws://127.0.0.1:7777/"), "index.html");
}

TEST(ResolveTarget, FragmentIsIgnored) {
    EXPECT_EQ(path_of("/#/room/K7M2QX"), "index.html");
}

TEST(ResolveTarget, PercentEscapesAreDecoded) {
    EXPECT_EQ(path_of("/a%20b.txt"), "a b.txt");
    EXPECT_EQ(path_of("/%69ndex.html"), "index.html");
    EXPECT_EQ(path_of("/caf%C3%A9.txt"), "caf\xc3\xa9.txt");
    EXPECT_EQ(path_of("/100%25.txt"), "100%.txt");
}

TEST(ResolveTarget, DotsInsideNamesAreFine) {
    EXPECT_EQ(path_of("/a..b.js"), "a..b.js");
    EXPECT_EQ(path_of("/js/x.min.js"), "js/x.min.js");
}

TEST(ResolveTarget, EmptyTargetIsRefused) {
    EXPECT_EQ(status_of(""), 400);
}

TEST(ResolveTarget, RelativeTargetIsRefused) {
    EXPECT_EQ(status_of("index.html"), 400);
    EXPECT_EQ(status_of("../etc/passwd"), 400);
}

TEST(ResolveTarget, AbsoluteFormIsRefused) {
    EXPECT_EQ(status_of("http://example.com/index.html"), 400);
    EXPECT_EQ(status_of("file:///etc/passwd"), 400);
}

TEST(ResolveTarget, AsteriskFormIsRefused) {
    EXPECT_EQ(status_of("*"), 400);
}

TEST(ResolveTarget, DoubleSlashIsRefused) {
    EXPECT_EQ(status_of("//etc/passwd"), 400);
    EXPECT_EQ(status_of("/js//app.js"), 400);
}

TEST(ResolveTarget, DotDotIsRefused) {
    EXPECT_EQ(status_of("/.."), 400);
    EXPECT_EQ(status_of("/../etc/passwd"), 400);
    EXPECT_EQ(status_of("/js/../index.html"), 400);
    EXPECT_EQ(status_of("/js/.."), 400);
    EXPECT_EQ(status_of("/js/../"), 400);
}

TEST(ResolveTarget, DotIsRefused) {
    EXPECT_EQ(status_of("/."), 400);
    EXPECT_EQ(status_of("/./index.html"), 400);
}

TEST(ResolveTarget, EncodedDotDotIsRefused) {
    EXPECT_EQ(status_of("/%2e%2e/etc/passwd"), 400);
    EXPECT_EQ(status_of("/%2E%2E/etc/passwd"), 400);
    EXPECT_EQ(status_of("/.%2e/etc/passwd"), 400);
    EXPECT_EQ(status_of("/%2e./etc/passwd"), 400);
    EXPECT_EQ(status_of("/js/%2e%2e"), 400);
}

TEST(ResolveTarget, EncodedSlashIsRefused) {
    EXPECT_EQ(status_of("/js%2fapp.js"), 400);
    EXPECT_EQ(status_of("/js%2Fapp.js"), 400);
    EXPECT_EQ(status_of("/..%2fetc%2fpasswd"), 400);
    EXPECT_EQ(status_of("/%2f"), 400);
}

TEST(ResolveTarget, BackslashIsRefused) {
    EXPECT_EQ(status_of("/js\\app.js"), 400);
    EXPECT_EQ(status_of("/..\\..\\etc\\passwd"), 400);
    EXPECT_EQ(status_of("/js%5capp.js"), 400);
    EXPECT_EQ(status_of("/..%5C..%5Cetc"), 400);
}

TEST(ResolveTarget, NulByteIsRefused) {
    EXPECT_EQ(status_of("/index.html\0.png"sv), 400);
    EXPECT_EQ(status_of("/index.html%00.png"), 400);
    EXPECT_EQ(status_of("/%00"), 400);
}

TEST(ResolveTarget, ControlCharactersAreRefused) {
    EXPECT_EQ(status_of("/a\x01"), 400);
    EXPECT_EQ(status_of("/a\x7f"), 400);
    EXPECT_EQ(status_of("/a%0d%0aSet-Cookie:%20x"), 400);
    EXPECT_EQ(status_of("/a%09"), 400);
    EXPECT_EQ(status_of("/a%7F"), 400);
}

TEST(ResolveTarget, RawSpaceAndRawNonAsciiAreRefused) {
    EXPECT_EQ(status_of("/a b.txt"), 400);
    EXPECT_EQ(status_of("/caf\xc3\xa9.txt"), 400);
}

TEST(ResolveTarget, BadPercentEscapesAreRefused) {
    EXPECT_EQ(status_of("/%"), 400);
    EXPECT_EQ(status_of("/%4"), 400);
    EXPECT_EQ(status_of("/%zz"), 400);
    EXPECT_EQ(status_of("/a%g0"), 400);
    EXPECT_EQ(status_of("/a%%41"), 400);
}

TEST(ResolveTarget, HiddenNamesAreNotFound) {
    EXPECT_EQ(status_of("/.git/config"), 404);
    EXPECT_EQ(status_of("/.env"), 404);
    EXPECT_EQ(status_of("/js/.secret.js"), 404);
    EXPECT_EQ(status_of("/%2egit/config"), 404);
}

TEST(ResolveTarget, LongestAllowedTargetIsResolved) {
    const std::string target = "/" + std::string(kMaxTargetBytes - 1, 'a');
    EXPECT_EQ(path_of(target), std::string(kMaxTargetBytes - 1, 'a'));
}

TEST(ResolveTarget, OverlongTargetIs414) {
    EXPECT_EQ(status_of("/" + std::string(kMaxTargetBytes, 'a')), 414);
    EXPECT_EQ(status_of(std::string(100000, '/')), 414);
}

// --- content types, ETags, If-None-Match -------------------------------------------------------

TEST(ContentType, ByExtension) {
    EXPECT_EQ(content_type_for("index.html"), "text/html; charset=utf-8");
    EXPECT_EQ(content_type_for("js/app.js"), "text/javascript; charset=utf-8");
    EXPECT_EQ(content_type_for("x.mjs"), "text/javascript; charset=utf-8");
    EXPECT_EQ(content_type_for("style.css"), "text/css; charset=utf-8");
    EXPECT_EQ(content_type_for("favicon.svg"), "image/svg+xml");
    EXPECT_EQ(content_type_for("img/dot.png"), "image/png");
    EXPECT_EQ(content_type_for("a.json"), "application/json");
    EXPECT_EQ(content_type_for("m.webmanifest"), "application/manifest+json");
    EXPECT_EQ(content_type_for("f.woff2"), "font/woff2");
    EXPECT_EQ(content_type_for("m.wasm"), "application/wasm");
}

TEST(ContentType, ExtensionIsCaseInsensitive) {
    EXPECT_EQ(content_type_for("INDEX.HTML"), "text/html; charset=utf-8");
    EXPECT_EQ(content_type_for("App.Js"), "text/javascript; charset=utf-8");
}

TEST(ContentType, UnknownIsOctetStream) {
    EXPECT_EQ(content_type_for("data"), "application/octet-stream");
    EXPECT_EQ(content_type_for("archive.tar.xz"), "application/octet-stream");
    EXPECT_EQ(content_type_for("dir.js/file"), "application/octet-stream");
    EXPECT_EQ(content_type_for("file."), "application/octet-stream");
}

TEST(ETag, IsTheQuotedFnv1a64) {
    EXPECT_EQ(etag_for(""), "\"cbf29ce484222325\"");
    EXPECT_EQ(etag_for("a"), "\"af63dc4c8601ec8c\"");
    EXPECT_EQ(etag_for("foobar"), "\"85944171f73967e8\"");
}

TEST(ETag, DiffersWhenContentDiffers) {
    EXPECT_NE(etag_for("export const a = 1;\n"), etag_for("export const a = 2;\n"));
}

TEST(IfNoneMatch, ExactTagMatches) {
    EXPECT_TRUE(if_none_match_matches("\"abc\"", "\"abc\""));
}

TEST(IfNoneMatch, WeakTagMatchesByWeakComparison) {
    EXPECT_TRUE(if_none_match_matches("W/\"abc\"", "\"abc\""));
}

TEST(IfNoneMatch, ListWithSpacesMatches) {
    EXPECT_TRUE(if_none_match_matches("\"x\", \"y\" ,\t\"abc\"", "\"abc\""));
}

TEST(IfNoneMatch, StarMatchesAnything) {
    EXPECT_TRUE(if_none_match_matches("*", "\"abc\""));
}

TEST(IfNoneMatch, OtherTagsDoNotMatch) {
    EXPECT_FALSE(if_none_match_matches("\"abd\"", "\"abc\""));
    EXPECT_FALSE(if_none_match_matches("\"abc", "\"abc\""));
    EXPECT_FALSE(if_none_match_matches("abc", "\"abc\""));
    EXPECT_FALSE(if_none_match_matches("", "\"abc\""));
    EXPECT_FALSE(if_none_match_matches(",,,", "\"abc\""));
    EXPECT_FALSE(if_none_match_matches("W/", "\"abc\""));
}

// --- responses ---------------------------------------------------------------------------------

TEST(StaticSite, GetIndexHasExactlyTheseHeaders) {
    const StaticResponse r = get("/");
    EXPECT_EQ(r.status, 200);
    EXPECT_EQ(r.body, "<!doctype html><title>t</title>");
    const std::vector<HttpHeader> expected{
        {"Content-Type", "text/html; charset=utf-8"},
        {"Content-Length", "31"},
        {"ETag", etag_for("<!doctype html><title>t</title>")},
        {"Cache-Control", "no-cache"},
        {"X-Content-Type-Options", "nosniff"},
        {"Content-Security-Policy",
         "default-src 'self'; connect-src 'self' ws: wss:; img-src 'self' data:; "
         "style-src 'self'; script-src 'self' 'wasm-unsafe-eval'; object-src 'none'; base-uri "
         "'none'; "
         "frame-ancestors 'none'; form-action 'none'"},
        {"Referrer-Policy", "no-referrer"},
    };
    EXPECT_EQ(r.headers, expected);
}

TEST(StaticSite, ScriptHasItsTypeAndNoPagePolicy) {
    const StaticResponse r = get("/js/app.js");
    EXPECT_EQ(r.status, 200);
    EXPECT_EQ(r.header("content-type"), "text/javascript; charset=utf-8");
    EXPECT_EQ(r.header("Content-Length"), "20");
    EXPECT_EQ(r.header("Content-Security-Policy"), "");
    EXPECT_EQ(r.body, "export const a = 1;\n");
}

TEST(StaticSite, BinaryFileKeepsItsNulBytes) {
    const StaticResponse r = get("/img/dot.png");
    EXPECT_EQ(r.status, 200);
    EXPECT_EQ(r.body.size(), 10U);
    EXPECT_EQ(r.body, "\x89PNG\r\n\x1a\n\0\0"sv);
    EXPECT_EQ(r.header("Content-Type"), "image/png");
}

TEST(StaticSite, QueryStringStillServesTheFile) {
    EXPECT_EQ(get("/?ws=ws://127.0.0.1:1/").status, 200);
    EXPECT_EQ(get("/js/app.js?v=1").body, "export const a = 1;\n");
}

TEST(StaticSite, EncodedNamesAreServed) {
    EXPECT_EQ(get("/a%20b.txt").body, "space");
    EXPECT_EQ(get("/caf%c3%a9.txt").body, "utf-8 name");
}

TEST(StaticSite, DirectoryIndex) {
    EXPECT_EQ(get("/js/").body, "<p>js</p>");
}

TEST(StaticSite, HeadHasTheGetHeadersAndNoBody) {
    const StaticResponse g = get("/style.css");
    const StaticResponse h = get("/style.css", "HEAD");
    EXPECT_EQ(h.status, 200);
    EXPECT_EQ(h.headers, g.headers);
    EXPECT_EQ(h.header("Content-Length"), "6");
    EXPECT_TRUE(h.body.empty());
}

TEST(StaticSite, MatchingETagIs304WithoutBody) {
    const std::string tag = etag_for("body{}");
    const std::string_view inm = tag;
    const StaticResponse r = site().respond({"GET", "/style.css", inm});
    EXPECT_EQ(r.status, 304);
    EXPECT_TRUE(r.body.empty());
    EXPECT_EQ(r.header("ETag"), tag);
    EXPECT_EQ(r.header("Cache-Control"), "no-cache");
    EXPECT_EQ(r.header("Content-Type"), "");
    EXPECT_EQ(r.header("Content-Length"), "");
}

TEST(StaticSite, HeadWithMatchingETagIs304) {
    const std::string tag = etag_for("body{}");
    const std::string_view inm = tag;
    EXPECT_EQ(site().respond({"HEAD", "/style.css", inm}).status, 304);
}

TEST(StaticSite, OtherETagIs200) {
    const StaticResponse r = site().respond({"GET", "/style.css", "\"0000000000000000\""sv});
    EXPECT_EQ(r.status, 200);
    EXPECT_EQ(r.body, "body{}");
}

TEST(StaticSite, StaleETagOfAnotherFileIs200) {
    const std::string other = etag_for("<p>js</p>");
    const std::string_view inm = other;
    EXPECT_EQ(site().respond({"GET", "/style.css", inm}).status, 200);
}

TEST(StaticSite, MissingFileIs404) {
    const StaticResponse r = get("/nothing.js");
    EXPECT_EQ(r.status, 404);
    EXPECT_EQ(r.body, "Not found.\n");
    EXPECT_EQ(r.header("Content-Type"), "text/plain; charset=utf-8");
    EXPECT_EQ(r.header("Content-Length"), "11");
    EXPECT_EQ(r.header("Cache-Control"), "no-store");
    EXPECT_EQ(r.header("ETag"), "");
}

TEST(StaticSite, DirectoryWithoutSlashIs404) {
    EXPECT_EQ(get("/js").status, 404);
    EXPECT_EQ(get("/img/").status, 404); // no img/index.html
}

TEST(StaticSite, HeadOfMissingFileIs404WithoutBody) {
    const StaticResponse r = get("/nothing.js", "HEAD");
    EXPECT_EQ(r.status, 404);
    EXPECT_TRUE(r.body.empty());
    EXPECT_EQ(r.header("Content-Length"), "11");
}

TEST(StaticSite, TraversalIs400AndServesNothing) {
    for (const char* target :
         {"/../index.html", "/%2e%2e/index.html", "/js/%2e%2e/index.html", "/js%2f..%2findex.html",
          "/..\\index.html", "//index.html", "/index.html%00", "/js/../../../etc/passwd"}) {
        const StaticResponse r = get(target);
        EXPECT_EQ(r.status, 400) << target;
        EXPECT_EQ(r.body, "Bad request: that path cannot name a file of this site.\n") << target;
        EXPECT_EQ(r.header("Cache-Control"), "no-store") << target;
    }
}

TEST(StaticSite, PostIs405WithAllow) {
    const StaticResponse r = get("/", "POST");
    EXPECT_EQ(r.status, 405);
    EXPECT_EQ(r.header("Allow"), "GET, HEAD");
    EXPECT_EQ(r.body, "Method not allowed: use GET or HEAD.\n");
}

TEST(StaticSite, EveryOtherMethodIs405) {
    for (const char* method :
         {"PUT", "DELETE", "PATCH", "OPTIONS", "TRACE", "CONNECT", "PROPFIND", "get", "Head", ""}) {
        const StaticResponse r = get("/index.html", method);
        EXPECT_EQ(r.status, 405) << method;
        EXPECT_EQ(r.header("Allow"), "GET, HEAD") << method;
    }
}

TEST(StaticSite, MethodIsCheckedBeforeThePath) {
    EXPECT_EQ(get("/../x", "DELETE").status, 405);
}

TEST(StaticSite, OverlongTargetIs414) {
    const std::string target = "/" + std::string(kMaxTargetBytes, 'a');
    const StaticResponse r = get(target);
    EXPECT_EQ(r.status, 414);
    EXPECT_EQ(r.body, "URI too long.\n");
    EXPECT_EQ(get(target, "POST").status, 414);
}

TEST(StaticSite, OverlongIfNoneMatchIs431) {
    const std::string inm(kMaxIfNoneMatchBytes + 1, 'x');
    const StaticResponse r = site().respond({"GET", "/", std::string_view(inm)});
    EXPECT_EQ(r.status, 431);
    EXPECT_EQ(r.body, "Request header fields too large.\n");
}

TEST(StaticSite, LongestIfNoneMatchIsRead) {
    std::string inm(kMaxIfNoneMatchBytes - 20, ' ');
    inm += etag_for("body{}");
    const StaticResponse r = site().respond({"GET", "/style.css", std::string_view(inm)});
    EXPECT_EQ(r.status, 304);
}

TEST(StaticSite, CountsItsFiles) {
    EXPECT_EQ(site().file_count(), 8U);
    EXPECT_TRUE(site().has("js/app.js"));
    EXPECT_FALSE(site().has("/js/app.js"));
}

// --- loading a directory -----------------------------------------------------------------------

class TempDir {
public:
    TempDir() {
        std::string templ = (fs::temp_directory_path() / "carrom-site-XXXXXX").string();
        path_ = ::mkdtemp(templ.data());
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }
    void write(const std::string& relative, const std::string& content) const {
        const fs::path p = path_ / relative;
        fs::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << content;
    }

private:
    fs::path path_;
};

TEST(StaticSiteDirectory, ServesItsFilesAndSkipsHiddenOnesAndLinks) {
    TempDir dir;
    dir.write("index.html", "<p>home</p>");
    dir.write("js/app.js", "1;");
    dir.write(".env", "SECRET=1");
    dir.write(".git/config", "[core]");
    dir.write("js/.cache/x.js", "2;");
    fs::create_symlink("/etc/hostname", dir.path() / "host.txt");
    fs::create_directory_symlink("/etc", dir.path() / "etc");
    SiteLoad load = StaticSite::from_directory(dir.path().string());
    ASSERT_TRUE(load.site) << load.error;
    EXPECT_EQ(load.site->file_count(), 2U);
    EXPECT_EQ(load.site->respond({"GET", "/", std::nullopt}).body, "<p>home</p>");
    EXPECT_EQ(load.site->respond({"GET", "/js/app.js", std::nullopt}).body, "1;");
    EXPECT_EQ(load.site->respond({"GET", "/host.txt", std::nullopt}).status, 404);
    EXPECT_EQ(load.site->respond({"GET", "/etc/passwd", std::nullopt}).status, 404);
    EXPECT_EQ(load.site->respond({"GET", "/.env", std::nullopt}).status, 404);
    EXPECT_EQ(load.site->total_bytes(), 13U);
}

TEST(StaticSiteDirectory, ReadsOnceSoLaterChangesAreNotServed) {
    TempDir dir;
    dir.write("index.html", "v1");
    SiteLoad load = StaticSite::from_directory(dir.path().string());
    ASSERT_TRUE(load.site) << load.error;
    dir.write("index.html", "v2");
    dir.write("new.js", "x");
    EXPECT_EQ(load.site->respond({"GET", "/", std::nullopt}).body, "v1");
    EXPECT_EQ(load.site->respond({"GET", "/new.js", std::nullopt}).status, 404);
}

TEST(StaticSiteDirectory, MissingDirectoryIsAnError) {
    const SiteLoad load = StaticSite::from_directory("/nonexistent/carrom-web");
    EXPECT_FALSE(load.site);
    EXPECT_EQ(load.error, "The web root /nonexistent/carrom-web is not a directory.");
}

TEST(StaticSiteDirectory, FileInsteadOfDirectoryIsAnError) {
    TempDir dir;
    dir.write("index.html", "x");
    const std::string file = (dir.path() / "index.html").string();
    const SiteLoad load = StaticSite::from_directory(file);
    EXPECT_FALSE(load.site);
    EXPECT_EQ(load.error, "The web root " + file + " is not a directory.");
}

TEST(StaticSiteDirectory, NoIndexIsAnError) {
    TempDir dir;
    dir.write("app.js", "x");
    const SiteLoad load = StaticSite::from_directory(dir.path().string());
    EXPECT_FALSE(load.site);
    EXPECT_EQ(load.error, "The web root " + dir.path().string() + " has no index.html.");
}

TEST(StaticSiteDirectory, LargeFileIsAnError) {
    TempDir dir;
    dir.write("index.html", "x");
    dir.write("big.bin", std::string(101, 'b'));
    SiteLimits limits;
    limits.max_file_bytes = 100;
    const SiteLoad load = StaticSite::from_directory(dir.path().string(), limits);
    EXPECT_FALSE(load.site);
    EXPECT_EQ(load.error, "The web root's file big.bin is larger than 100 bytes.");
}

TEST(StaticSiteDirectory, TooManyFilesIsAnError) {
    TempDir dir;
    for (int i = 0; i < 4; ++i) {
        dir.write("f" + std::to_string(i) + ".txt", "x");
    }
    SiteLimits limits;
    limits.max_files = 3;
    const SiteLoad load = StaticSite::from_directory(dir.path().string(), limits);
    EXPECT_FALSE(load.site);
    EXPECT_NE(load.error.find("holds more than 3 files"), std::string::npos) << load.error;
}

TEST(StaticSiteDirectory, TooManyBytesIsAnError) {
    TempDir dir;
    dir.write("index.html", std::string(60, 'x'));
    dir.write("more.txt", std::string(60, 'y'));
    SiteLimits limits;
    limits.max_total_bytes = 100;
    const SiteLoad load = StaticSite::from_directory(dir.path().string(), limits);
    EXPECT_FALSE(load.site);
    EXPECT_NE(load.error.find("or 100 bytes"), std::string::npos) << load.error;
}

// --- the files the build embeds ------------------------------------------------------------------

TEST(EmbeddedWebFiles, AreExactlyTheFilesOfWeb) {
    const char* source = std::getenv("CARROM_SOURCE_DIR");
    ASSERT_NE(source, nullptr) << "CARROM_SOURCE_DIR is set by ctest";
    SiteLoad from_disk = StaticSite::from_directory(std::string(source) + "/web");
    ASSERT_TRUE(from_disk.site) << from_disk.error;
    const std::span<const EmbeddedFile> embedded = embedded_web_files();
    EXPECT_EQ(embedded.size(), from_disk.site->file_count());
    std::set<std::string> paths;
    for (const EmbeddedFile& f : embedded) {
        paths.insert(std::string(f.path));
        const std::string target = "/" + std::string(f.path);
        const StaticResponse disk = from_disk.site->respond({"GET", target, std::nullopt});
        EXPECT_EQ(disk.status, 200) << f.path;
#ifdef CARROM_WEB_WASM_PATH
        // web/'s copy of the engine is an empty placeholder; the build embeds the module that
        // emscripten made instead (wasm/CMakeLists.txt).
        if (f.path == "js/carrom_engine.wasm") {
            EXPECT_EQ(test_support::read_file(CARROM_WEB_WASM_PATH), f.content) << f.path;
            continue;
        }
#endif
        EXPECT_EQ(disk.body, f.content) << f.path << " differs from web/: rebuild";
    }
    EXPECT_TRUE(paths.count("index.html"));
    EXPECT_TRUE(paths.count("js/app.js"));
}

TEST(EmbeddedWebFiles, ServeThePageWithTheRightTypes) {
    const StaticSite s = StaticSite::from_files(embedded_web_files());
    EXPECT_EQ(s.respond({"GET", "/", std::nullopt}).header("Content-Type"),
              "text/html; charset=utf-8");
    for (const EmbeddedFile& f : embedded_web_files()) {
        if (f.path.ends_with(".js")) {
            EXPECT_EQ(
                s.respond({"HEAD", "/" + std::string(f.path), std::nullopt}).header("Content-Type"),
                "text/javascript; charset=utf-8")
                << f.path;
        }
    }
}

} // namespace
} // namespace carrom::server
