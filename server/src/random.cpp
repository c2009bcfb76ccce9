#include "carrom/server/random.hpp"

#include "carrom/proto/limits.hpp"

#include <random>

namespace carrom::server {

std::uint64_t SystemRandom::next_u64() {
    std::lock_guard lock(mutex_);
    std::random_device device;
    const std::uint64_t high = device();
    const std::uint64_t low = device();
    return (high << 32U) ^ low;
}

std::uint64_t SeededRandom::next_u64() {
    std::lock_guard lock(mutex_);
    state_ += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30U)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27U)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31U);
}

std::string make_resume_token(RandomSource& random) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string token;
    token.reserve(proto::kResumeTokenLength);
    for (int word = 0; word < 2; ++word) {
        std::uint64_t bits = random.next_u64();
        for (int i = 0; i < 16; ++i) {
            token.push_back(kHex[bits & 0xfU]);
            bits >>= 4U;
        }
    }
    return token;
}

std::string make_room_code(RandomSource& random) {
    constexpr std::uint64_t kAlphabetSize = sizeof(proto::kRoomCodeAlphabet) - 1;
    // Largest multiple of the alphabet size that fits in a byte: bytes at or above it are
    // rejected so every character is equally likely.
    constexpr std::uint64_t kLimit = 256 / kAlphabetSize * kAlphabetSize;
    std::string code;
    while (code.size() < proto::kRoomCodeLength) {
        std::uint64_t bits = random.next_u64();
        for (int i = 0; i < 8 && code.size() < proto::kRoomCodeLength; ++i) {
            const std::uint64_t byte = bits & 0xffU;
            bits >>= 8U;
            if (byte < kLimit) {
                code.push_back(proto::kRoomCodeAlphabet[byte % kAlphabetSize]);
            }
        }
    }
    return code;
}

} // namespace carrom::server
