#include "api_fetcher.hpp"

#include "carrom/net/http_get.hpp"
#include "carrom/net/ws_url.hpp"

#include <algorithm>
#include <chrono>
#include <utility>
#include <variant>

namespace carrom::client::app {

ApiFetcher::ApiFetcher(const std::string& ws_url, std::string ca_file)
    : base_(http_base(ws_url)), ca_file_(std::move(ca_file)) {}

std::string ApiFetcher::http_base(const std::string& ws_url) {
    const auto parsed = net::parse_ws_url(ws_url);
    const auto* url = std::get_if<net::WsUrl>(&parsed);
    if (url == nullptr) {
        return "";
    }
    return (url->tls ? "https://" : "http://") + url->authority();
}

bool ApiFetcher::get(std::string key, const std::string& path, std::size_t max_body_bytes) {
    if (base_.empty() || pending_.size() >= kMaxInFlight) {
        return false;
    }
    net::HttpLimits limits;
    limits.max_body_bytes = max_body_bytes;
    limits.timeout = std::chrono::milliseconds(5000);
    std::string url = base_ + path;
    auto task = [url = std::move(url), limits, ca = ca_file_]() {
        auto got = net::http_get_any_status(url, limits, ca);
        ApiAnswer answer;
        if (auto* problem = std::get_if<std::string>(&got)) {
            answer.failure = std::move(*problem);
        } else {
            auto& response = std::get<net::HttpResponse>(got);
            answer.status = response.status;
            answer.body = std::move(response.body);
        }
        return answer;
    };
    pending_.push_back(Pending{std::move(key), std::async(std::launch::async, std::move(task))});
    return true;
}

std::vector<ApiFetcher::Done> ApiFetcher::take_done() {
    std::vector<Done> done;
    for (auto it = pending_.begin(); it != pending_.end();) {
        if (it->answer.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
            done.push_back(Done{std::move(it->key), it->answer.get()});
            it = pending_.erase(it);
        } else {
            ++it;
        }
    }
    return done;
}

bool ApiFetcher::running(const std::string& key) const {
    return std::any_of(pending_.begin(), pending_.end(),
                       [&](const Pending& p) { return p.key == key; });
}

} // namespace carrom::client::app
