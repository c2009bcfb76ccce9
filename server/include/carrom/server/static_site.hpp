#pragma once
// The web client's files over plain HTTP, free of Boost and sockets: given a request's method,
// target and If-None-Match, decides the status, the headers and the body (docs/web.md,
// "Serving"). The files are embedded in the binary at build time (web_assets.hpp) or read once
// from a directory. Only those files can ever be served: every target is normalised first and a
// target that could name anything else (`..`, `%2e%2e`, `%2f`, a backslash, a NUL byte, a
// control character, `//`, a target that is not an absolute path) is refused with 400.
//
// Statuses: 200 (304 when If-None-Match names the file's ETag), 400 bad target, 404 no such
// file, 405 a method other than GET or HEAD (with Allow), 414 a target over kMaxTargetBytes,
// 431 an If-None-Match header over kMaxIfNoneMatchBytes. HEAD answers the GET's headers
// (Content-Length included) with no body.

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace carrom::server {

inline constexpr std::size_t kMaxTargetBytes = 2048;
inline constexpr std::size_t kMaxIfNoneMatchBytes = 2048;

// A file as the build embeds it: path relative to the site root, '/'-separated ("js/app.js").
struct EmbeddedFile {
    std::string_view path;
    std::string_view content;
};

struct StaticRequest {
    std::string_view method; // "GET", "HEAD", ... (case-sensitive, as HTTP methods are)
    std::string_view target; // the request target as received, e.g. "/js/app.js?v=2"
    std::optional<std::string_view> if_none_match;
};

struct HttpHeader {
    std::string name;
    std::string value;
    friend bool operator==(const HttpHeader&, const HttpHeader&) = default;
};

struct StaticResponse {
    int status = 200;
    std::vector<HttpHeader> headers;
    // Points into the site's files or a static sentence: valid while the site lives.
    std::string_view body;
    // The value of header `name` (case-insensitive), empty when absent.
    std::string_view header(std::string_view name) const;
};

// Limits for a directory given with --web-root (the embedded files are whatever the build put
// in; web/ is about 170 KB).
struct SiteLimits {
    std::size_t max_files = 1000;
    std::size_t max_file_bytes = std::size_t{8} << 20;
    std::size_t max_total_bytes = std::size_t{64} << 20;
};

// A normalised target: the file path relative to the site root, or the status refusing it.
std::variant<std::string, int> resolve_target(std::string_view target);

// Content-Type for a path, by its extension (application/octet-stream when unknown).
std::string_view content_type_for(std::string_view path);

// The strong ETag of a content: a quoted 64-bit FNV-1a hash in hex.
std::string etag_for(std::string_view content);

// Whether an If-None-Match value (a list of entity tags, or "*") matches `etag` (weak
// comparison, as RFC 9110 asks for If-None-Match).
bool if_none_match_matches(std::string_view header_value, std::string_view etag);

struct SiteLoad;

// Immutable once built; responses point into it, so it is not copyable (moving keeps the files
// where they are).
class StaticSite {
public:
    StaticSite(const StaticSite&) = delete;
    StaticSite& operator=(const StaticSite&) = delete;
    StaticSite(StaticSite&&) = default;
    StaticSite& operator=(StaticSite&&) = default;

    // From files embedded at build time (copied in).
    static StaticSite from_files(std::span<const EmbeddedFile> files);
    // Reads every regular file under `root` once (hidden entries and symbolic links skipped).
    // Fails with a sentence when root is not a readable directory, has no index.html, or
    // exceeds the limits.
    static SiteLoad from_directory(const std::string& root, const SiteLimits& limits = {});

    StaticResponse respond(const StaticRequest& request) const;

    std::size_t file_count() const { return files_.size(); }
    std::size_t total_bytes() const;
    bool has(std::string_view path) const { return files_.find(path) != files_.end(); }

private:
    struct File {
        std::string content;
        std::string_view type;
        std::string etag;
    };
    StaticSite() = default;
    void add(std::string path, std::string content);

    std::map<std::string, File, std::less<>> files_; // nodes never move: bodies point into them
};

struct SiteLoad {
    std::optional<StaticSite> site; // empty on failure
    std::string error;              // one sentence when it failed
};

} // namespace carrom::server
