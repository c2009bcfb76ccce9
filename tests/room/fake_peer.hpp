#pragma once
// A Peer that records what a room sends it, decoded, for the room tests.

#include "carrom/proto/codec.hpp"
#include "carrom/room/peer.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace carrom::room::testing {

class FakePeer final : public Peer {
public:
    FakePeer(std::int64_t id, std::string name) : id_(id), name_(std::move(name)) {}

    std::int64_t player_id() const override { return id_; }
    const std::string& name() const override { return name_; }
    std::string resume_token() const override { return token; }
    void send(Outgoing message) override {
        const auto decoded = proto::decode_server(*message.text);
        EXPECT_TRUE(decoded.ok()) << decoded.error.message << " in " << *message.text;
        if (decoded.ok()) {
            received.push_back(*decoded.message);
            kinds.push_back(message.kind);
        }
    }
    bool take_keyframe_request() override {
        const bool r = wants_keyframe;
        wants_keyframe = false;
        return r;
    }
    void close(int code, std::string) override { closed_with = code; }

    template <class T> std::vector<T> all() const {
        std::vector<T> out;
        for (const auto& m : received) {
            if (const auto* t = std::get_if<T>(&m)) {
                out.push_back(*t);
            }
        }
        return out;
    }
    template <class T> std::vector<T> events() const {
        std::vector<T> out;
        for (const auto& e : all<proto::Event>()) {
            if (const auto* t = std::get_if<T>(&e)) {
                out.push_back(*t);
            }
        }
        return out;
    }
    std::vector<std::string> error_codes() const {
        std::vector<std::string> out;
        for (const auto& e : all<proto::Error>()) {
            out.push_back(e.code);
        }
        return out;
    }
    std::string last_error() const {
        const auto codes = error_codes();
        return codes.empty() ? std::string() : codes.back();
    }
    proto::RoomState last_room_state() const {
        const auto states = all<proto::RoomState>();
        return states.empty() ? proto::RoomState{} : states.back();
    }
    void clear() {
        received.clear();
        kinds.clear();
    }

    std::vector<proto::ServerMessage> received;
    std::vector<MessageKind> kinds;
    bool wants_keyframe = false;
    std::string token; // resume_token()
    int closed_with = 0;

private:
    std::int64_t id_;
    std::string name_;
};

} // namespace carrom::room::testing
