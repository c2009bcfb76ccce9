#include "replay_source.hpp"

#include "carrom/net/http_get.hpp"
#include "carrom/proto/journal_json.hpp"

#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

namespace carrom::client::app {

namespace {

// At most max_bytes + 1 bytes of the stream (one more than allowed shows it is too long).
std::string read_limited(std::istream& in, std::size_t max_bytes) {
    std::string text;
    char buffer[65536];
    while (in && text.size() <= max_bytes) {
        in.read(buffer, sizeof buffer);
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
    }
    return text;
}

std::variant<std::string, std::string> read_source(const std::string& source) {
    using Text = std::variant<std::string, std::string>;
    if (source.rfind("http://", 0) == 0 || source.rfind("https://", 0) == 0) {
        net::HttpLimits limits;
        limits.max_body_bytes = proto::kMaxJournalBytes;
        auto got = net::http_get(source, limits);
        if (auto* problem = std::get_if<std::string>(&got)) {
            return Text{std::in_place_index<1>, std::move(*problem)};
        }
        return Text{std::in_place_index<0>, std::move(std::get<net::HttpResponse>(got).body)};
    }
    std::string text;
    if (source == "-") {
        text = read_limited(std::cin, proto::kMaxJournalBytes);
    } else {
        std::ifstream file(source, std::ios::binary);
        if (!file) {
            return Text{std::in_place_index<1>, "cannot read " + source + "."};
        }
        text = read_limited(file, proto::kMaxJournalBytes);
        if (file.bad()) {
            return Text{std::in_place_index<1>, "cannot read " + source + "."};
        }
    }
    return Text{std::in_place_index<0>, std::move(text)};
}

} // namespace

std::variant<ReplayModel, std::string> load_replay(const std::string& source) {
    using Result = std::variant<ReplayModel, std::string>;
    auto text = read_source(source);
    if (text.index() == 1) {
        return Result{std::in_place_index<1>, std::get<1>(std::move(text))};
    }
    auto loaded = ReplayModel::load_text(std::get<0>(text));
    if (auto* error = std::get_if<proto::Error>(&loaded)) {
        std::ostringstream line;
        line << (source == "-" ? "standard input" : source) << ": "
             << (error->path.empty() ? "" : error->path + ": ") << error->message << " ("
             << error->code << ")";
        return Result{std::in_place_index<1>, line.str()};
    }
    return Result{std::in_place_index<0>, std::get<ReplayModel>(std::move(loaded))};
}

} // namespace carrom::client::app
