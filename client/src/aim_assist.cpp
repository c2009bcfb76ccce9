#include "carrom/client/aim_assist.hpp"

#include "carrom/rules/placement.hpp"

#include <algorithm>

namespace carrom::client {

namespace {

bool same_bodies(const std::vector<Body>& a, const std::vector<Body>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Body& x, const Body& y) {
        return x.id == y.id && x.kind == y.kind && x.pos_px == y.pos_px &&
               x.vel_px_s == y.vel_px_s && x.pocketed == y.pocketed;
    });
}

} // namespace

AimAssist::AimAssist(const PhysicsConfig& physics) : physics_(physics), engine_(physics) {}

std::optional<FirstContact> AimAssist::guide(std::span<const BodyState> board, rules::Side side,
                                             const Shot& shot) {
    std::vector<Body> scene;
    scene.reserve(board.size() + 1);
    for (const BodyState& b : board) {
        if (b.kind != BodyKind::Striker) {
            scene.push_back({b.id, b.kind, b.pos_px, {}, b.pocketed});
        }
    }
    std::sort(scene.begin(), scene.end(), [](const Body& a, const Body& b) { return a.id < b.id; });
    scene.push_back(rules::striker_for(physics_, side, shot));
    if (answered_ && same_bodies(scene, scene_)) {
        return answer_;
    }
    scene_ = std::move(scene);
    answer_ = first_contact(engine_, scene_);
    answered_ = true;
    ++runs_;
    return answer_;
}

} // namespace carrom::client
