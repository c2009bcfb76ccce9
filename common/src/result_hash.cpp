#include "carrom/result_hash.hpp"
#include "carrom/double_bits.hpp"

namespace carrom {

void ResultHash::add_word(std::uint64_t word) {
    for (int byte = 0; byte < 8; ++byte) {
        value_ ^= (word >> (8 * byte)) & 0xFFU;
        value_ *= 1099511628211ULL; // the FNV-1a 64-bit prime
    }
}

void ResultHash::add_double(double x) {
    add_word(double_bits(x));
}

void ResultHash::add_int(int x) {
    add_word(static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)));
}

void ResultHash::add(const SimResult& result) {
    for (const Event& e : result.events) {
        add_double(e.t_s);
        add_int(static_cast<int>(e.kind));
        add_int(e.a);
        add_int(e.b);
        add_double(e.impulse);
        add_double(e.pos_px.x);
        add_double(e.pos_px.y);
    }
    for (const Body& b : result.bodies) {
        add_double(b.pos_px.x);
        add_double(b.pos_px.y);
        add_double(b.vel_px_s.x);
        add_double(b.vel_px_s.y);
        add_int(b.pocketed ? 1 : 0);
    }
    add_double(result.end_time_s);
    for (int id : result.pocket_order) {
        add_int(id);
    }
}

} // namespace carrom
