#include "carrom/golden/golden_json.hpp"

#include "carrom/proto/types.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

namespace carrom::golden {

std::vector<StreamLine> parse_stream(const std::string& jsonl) {
    std::vector<StreamLine> out;
    std::istringstream in(jsonl);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty()) {
            continue;
        }
        const nlohmann::json j = nlohmann::json::parse(line);
        out.push_back({j.at("at").get<double>(), j.at("line").get<std::string>()});
    }
    return out;
}

std::string format_stream(const std::vector<StreamLine>& stream) {
    std::string out;
    for (const StreamLine& s : stream) {
        out += nlohmann::json{{"at", rounded(s.at_s)}, {"line", s.text}}.dump() + "\n";
    }
    return out;
}

double rounded(double x) {
    const double r = std::round(x * 1e6) / 1e6;
    return r == 0.0 ? 0.0 : r; // no -0
}

BodyKind kind_named(const std::string& name) {
    BodyKind kind = BodyKind::Black;
    proto::parse(name, kind);
    return kind;
}

std::optional<std::string> read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

bool write_text(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
    return static_cast<bool>(out);
}

namespace {

// Containers whose one-line text is short, and everything below the third level, stay on one
// line; longer ones put each item on a line of its own (diffs of regenerated files stay small).
void format_into(std::string& out, const nlohmann::json& value, int depth) {
    const std::string line = value.dump();
    if (!value.is_structured() || value.empty() || depth >= 3 || line.size() <= 100) {
        out += line;
        return;
    }
    const std::string indent(static_cast<std::size_t>(depth + 1), ' ');
    out += value.is_array() ? "[\n" : "{\n";
    bool first = true;
    for (auto it = value.begin(); it != value.end(); ++it) {
        out += (first ? "" : ",\n") + indent;
        first = false;
        if (value.is_object()) {
            out += nlohmann::json(it.key()).dump() + ": ";
        }
        format_into(out, *it, depth + 1);
    }
    out +=
        "\n" + std::string(static_cast<std::size_t>(depth), ' ') + (value.is_array() ? "]" : "}");
}

} // namespace

std::string format_case(const nlohmann::json& value) {
    std::string out;
    format_into(out, value, 0);
    return out + "\n";
}

std::string first_difference(const nlohmann::json& expected, const nlohmann::json& actual,
                             const std::string& path) {
    if (expected.is_number() && actual.is_number()) {
        const double e = expected.get<double>();
        const double a = actual.get<double>();
        return std::abs(e - a) <= kTolerance
                   ? std::string()
                   : path + ": expected " + expected.dump() + ", got " + actual.dump();
    }
    if (expected.type() != actual.type()) {
        return path + ": expected " + expected.dump() + ", got " + actual.dump();
    }
    if (expected.is_array()) {
        if (expected.size() != actual.size()) {
            return path + ": expected " + std::to_string(expected.size()) + " items, got " +
                   std::to_string(actual.size()) + " (" + actual.dump() + ")";
        }
        for (std::size_t i = 0; i < expected.size(); ++i) {
            std::string d =
                first_difference(expected[i], actual[i], path + "[" + std::to_string(i) + "]");
            if (!d.empty()) {
                return d;
            }
        }
        return {};
    }
    if (expected.is_object()) {
        for (const auto& [key, value] : expected.items()) {
            if (!actual.contains(key)) {
                return path + "." + key + ": missing";
            }
            std::string d = first_difference(value, actual.at(key), path + "." + key);
            if (!d.empty()) {
                return d;
            }
        }
        for (const auto& [key, value] : actual.items()) {
            if (!expected.contains(key)) {
                return path + "." + key + ": not expected (" + value.dump() + ")";
            }
        }
        return {};
    }
    return expected == actual ? std::string()
                              : path + ": expected " + expected.dump() + ", got " + actual.dump();
}

} // namespace carrom::golden
