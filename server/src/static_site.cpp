#include "carrom/server/static_site.hpp"

#include "hex_digit.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace carrom::server {
namespace {

// Every file revalidates (no-cache + ETag): the files have no version in their names, and a
// page must never mix modules from two server versions. Unchanged files cost a 304.
constexpr std::string_view kCacheFiles = "no-cache";
constexpr std::string_view kCacheErrors = "no-store";
// The page loads only its own files and talks only to its own server (ws: and wss: for the
// WebSocket, which browsers do not all cover by 'self'); 'wasm-unsafe-eval' lets it compile its
// own WebAssembly engine (js/carrom_engine.wasm) and allows no JavaScript eval.
constexpr std::string_view kHtmlPolicy =
    "default-src 'self'; connect-src 'self' ws: wss:; img-src 'self' data:; "
    "style-src 'self'; script-src 'self' 'wasm-unsafe-eval'; object-src 'none'; base-uri 'none'; "
    "frame-ancestors 'none'; form-action 'none'";

char lower(char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                              [](char x, char y) { return lower(x) == lower(y); });
}

// A byte that may never appear in a path, raw or percent-encoded: controls (NUL included),
// DEL, and the backslash (a separator elsewhere).
bool forbidden_byte(unsigned char c) {
    return c < 0x20 || c == 0x7f || c == '\\';
}

// Percent-decodes one segment (no '/' inside). Refuses bad escapes, forbidden bytes and an
// encoded '/', which would let one segment pass as two.
std::optional<std::string> decode_segment(std::string_view raw) {
    std::string out;
    out.reserve(raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) {
        const auto c = static_cast<unsigned char>(raw[i]);
        if (c >= 0x80 || c == ' ' || forbidden_byte(c)) {
            return std::nullopt; // browsers send these percent-encoded
        }
        if (c != '%') {
            out.push_back(static_cast<char>(c));
            continue;
        }
        if (raw.size() - i < 3) {
            return std::nullopt; // "%" or "%4" at the end
        }
        const int hi = hex_value(raw[i + 1]);
        const int lo = hex_value(raw[i + 2]);
        if (hi < 0 || lo < 0) {
            return std::nullopt;
        }
        const auto decoded = static_cast<unsigned char>(hi * 16 + lo);
        if (decoded == '/' || forbidden_byte(decoded)) {
            return std::nullopt;
        }
        out.push_back(static_cast<char>(decoded));
        i += 2;
    }
    return out;
}

constexpr std::array<std::pair<std::string_view, std::string_view>, 16> kTypes{{
    {".html", "text/html; charset=utf-8"},
    {".js", "text/javascript; charset=utf-8"},
    {".mjs", "text/javascript; charset=utf-8"},
    {".css", "text/css; charset=utf-8"},
    {".json", "application/json"},
    {".webmanifest", "application/manifest+json"},
    {".svg", "image/svg+xml"},
    {".png", "image/png"},
    {".jpg", "image/jpeg"},
    {".jpeg", "image/jpeg"},
    {".ico", "image/x-icon"},
    {".webp", "image/webp"},
    {".woff2", "font/woff2"},
    {".wasm", "application/wasm"},
    {".txt", "text/plain; charset=utf-8"},
    {".md", "text/markdown; charset=utf-8"},
}};

void add_header(StaticResponse& r, std::string_view name, std::string_view value) {
    r.headers.push_back({std::string(name), std::string(value)});
}

// A refusal: a one-line sentence as plain text, never cached.
StaticResponse refusal(int status, std::string_view sentence, bool head) {
    StaticResponse r;
    r.status = status;
    add_header(r, "Content-Type", "text/plain; charset=utf-8");
    add_header(r, "Content-Length", std::to_string(sentence.size()));
    add_header(r, "Cache-Control", kCacheErrors);
    add_header(r, "X-Content-Type-Options", "nosniff");
    if (status == 405) {
        add_header(r, "Allow", "GET, HEAD");
    }
    r.body = head ? std::string_view{} : sentence;
    return r;
}

std::string_view refusal_sentence(int status) {
    switch (status) {
    case 400:
        return "Bad request: that path cannot name a file of this site.\n";
    case 404:
        return "Not found.\n";
    case 405:
        return "Method not allowed: use GET or HEAD.\n";
    case 414:
        return "URI too long.\n";
    case 431:
        return "Request header fields too large.\n";
    default:
        return "Error.\n";
    }
}

bool is_hidden(const std::filesystem::path& relative) {
    return std::any_of(relative.begin(), relative.end(), [](const std::filesystem::path& part) {
        const std::string s = part.string();
        return !s.empty() && s.front() == '.';
    });
}

} // namespace

std::string_view StaticResponse::header(std::string_view name) const {
    for (const HttpHeader& h : headers) {
        if (iequals(h.name, name)) {
            return h.value;
        }
    }
    return {};
}

std::variant<std::string, int> resolve_target(std::string_view target) {
    if (target.size() > kMaxTargetBytes) {
        return 414;
    }
    // Origin form only: "/path[?query]". Absolute form ("http://host/"), authority form and
    // "*" are refused, as is anything relative.
    if (target.empty() || target.front() != '/') {
        return 400;
    }
    const std::size_t end = target.find_first_of("?#");
    const std::string_view path = target.substr(1, end == std::string_view::npos ? end : end - 1);
    std::string out;
    std::size_t start = 0;
    while (start <= path.size()) {
        const std::size_t slash = path.find('/', start);
        const std::size_t stop = slash == std::string_view::npos ? path.size() : slash;
        const std::string_view raw = path.substr(start, stop - start);
        const bool last = slash == std::string_view::npos;
        if (raw.empty()) {
            if (!last) {
                return 400; // "//": an empty segment (as in "//etc/passwd")
            }
            out += "index.html"; // "/" or "/dir/": the directory's index
            break;
        }
        const std::optional<std::string> segment = decode_segment(raw);
        if (!segment || segment->empty() || *segment == "." || *segment == "..") {
            return 400;
        }
        if (segment->front() == '.') {
            return 404; // hidden files are never part of the site
        }
        out += *segment;
        if (last) {
            break;
        }
        out += '/';
        start = slash + 1;
    }
    return out;
}

std::string_view content_type_for(std::string_view path) {
    const std::size_t dot = path.rfind('.');
    const std::size_t slash = path.rfind('/');
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
        return "application/octet-stream";
    }
    const std::string_view ext = path.substr(dot);
    for (const auto& [known, type] : kTypes) {
        if (iequals(ext, known)) {
            return type;
        }
    }
    return "application/octet-stream";
}

std::string etag_for(std::string_view content) {
    std::uint64_t h = 14695981039346656037ULL;
    for (char c : content) {
        h ^= static_cast<unsigned char>(c);
        h *= 1099511628211ULL;
    }
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out = "\"";
    for (int shift = 60; shift >= 0; shift -= 4) {
        out.push_back(kHex[(h >> shift) & 0xF]);
    }
    out.push_back('"');
    return out;
}

bool if_none_match_matches(std::string_view value, std::string_view etag) {
    const auto opaque = [](std::string_view tag) {
        return tag.substr(0, 2) == "W/" ? tag.substr(2) : tag;
    };
    std::size_t start = 0;
    while (start <= value.size()) {
        std::size_t comma = value.find(',', start);
        if (comma == std::string_view::npos) {
            comma = value.size();
        }
        std::string_view item = value.substr(start, comma - start);
        while (!item.empty() && (item.front() == ' ' || item.front() == '\t')) {
            item.remove_prefix(1);
        }
        while (!item.empty() && (item.back() == ' ' || item.back() == '\t')) {
            item.remove_suffix(1);
        }
        if (item == "*") {
            return true;
        }
        const std::string_view tag = opaque(item);
        if (tag.size() >= 2 && tag.front() == '"' && tag.back() == '"' && tag == opaque(etag)) {
            return true;
        }
        start = comma + 1;
    }
    return false;
}

void StaticSite::add(std::string path, std::string content) {
    File& f = files_[path];
    f.type = content_type_for(path);
    f.etag = etag_for(content);
    f.content = std::move(content);
}

StaticSite StaticSite::from_files(std::span<const EmbeddedFile> files) {
    StaticSite site;
    for (const EmbeddedFile& f : files) {
        site.add(std::string(f.path), std::string(f.content));
    }
    return site;
}

SiteLoad StaticSite::from_directory(const std::string& root, const SiteLimits& limits) {
    namespace fs = std::filesystem;
    SiteLoad load;
    std::error_code ec;
    if (!fs::is_directory(root, ec)) {
        load.error = "The web root " + root + " is not a directory.";
        return load;
    }
    StaticSite site;
    std::size_t total = 0;
    fs::recursive_directory_iterator it(root, fs::directory_options::none, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        const fs::path relative = it->path().lexically_relative(root);
        const fs::file_status status = it->symlink_status(ec);
        if (ec) {
            break;
        }
        if (is_hidden(relative) || fs::is_symlink(status)) {
            if (fs::is_directory(status)) {
                it.disable_recursion_pending(); // not into .git or a linked directory
            }
            continue;
        }
        if (!fs::is_regular_file(status)) {
            continue;
        }
        const std::string name = relative.generic_string();
        const std::uintmax_t size = it->file_size(ec);
        if (ec) {
            break;
        }
        if (size > limits.max_file_bytes) {
            load.error = "The web root's file " + name + " is larger than " +
                         std::to_string(limits.max_file_bytes) + " bytes.";
            return load;
        }
        total += static_cast<std::size_t>(size);
        if (site.files_.size() >= limits.max_files || total > limits.max_total_bytes) {
            load.error = "The web root " + root + " holds more than " +
                         std::to_string(limits.max_files) + " files or " +
                         std::to_string(limits.max_total_bytes) + " bytes.";
            return load;
        }
        std::ifstream in(it->path(), std::ios::binary);
        std::string content(static_cast<std::size_t>(size), '\0');
        in.read(content.data(), static_cast<std::streamsize>(content.size()));
        if (!in || in.gcount() != static_cast<std::streamsize>(content.size())) {
            load.error = "Cannot read " + it->path().string() + ".";
            return load;
        }
        site.add(name, std::move(content));
    }
    if (ec) {
        load.error = "Cannot read the web root " + root + ": " + ec.message() + ".";
        return load;
    }
    if (!site.has("index.html")) {
        load.error = "The web root " + root + " has no index.html.";
        return load;
    }
    load.site.emplace(std::move(site));
    return load;
}

std::size_t StaticSite::total_bytes() const {
    std::size_t total = 0;
    for (const auto& [path, file] : files_) {
        total += file.content.size();
    }
    return total;
}

StaticResponse StaticSite::respond(const StaticRequest& request) const {
    const bool head = request.method == "HEAD";
    if (request.target.size() > kMaxTargetBytes) {
        return refusal(414, refusal_sentence(414), head);
    }
    if (!head && request.method != "GET") {
        return refusal(405, refusal_sentence(405), false);
    }
    if (request.if_none_match && request.if_none_match->size() > kMaxIfNoneMatchBytes) {
        return refusal(431, refusal_sentence(431), head);
    }
    const std::variant<std::string, int> resolved = resolve_target(request.target);
    if (const int* status = std::get_if<int>(&resolved)) {
        return refusal(*status, refusal_sentence(*status), head);
    }
    const auto it = files_.find(std::get<std::string>(resolved));
    if (it == files_.end()) {
        return refusal(404, refusal_sentence(404), head);
    }
    const File& file = it->second;
    StaticResponse r;
    const bool not_modified =
        request.if_none_match && if_none_match_matches(*request.if_none_match, file.etag);
    r.status = not_modified ? 304 : 200;
    if (!not_modified) {
        add_header(r, "Content-Type", file.type);
        add_header(r, "Content-Length", std::to_string(file.content.size()));
    }
    add_header(r, "ETag", file.etag);
    add_header(r, "Cache-Control", kCacheFiles);
    add_header(r, "X-Content-Type-Options", "nosniff");
    if (file.type.starts_with("text/html")) {
        add_header(r, "Content-Security-Policy", kHtmlPolicy);
        add_header(r, "Referrer-Policy", "no-referrer");
    }
    if (!not_modified && !head) {
        r.body = file.content;
    }
    return r;
}

} // namespace carrom::server
