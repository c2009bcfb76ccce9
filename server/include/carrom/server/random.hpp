#pragma once
// Randomness for resume tokens and room codes, behind an interface so tests are repeatable.

#include <cstdint>
#include <mutex>
#include <string>

namespace carrom::server {

class RandomSource {
public:
    virtual ~RandomSource() = default;
    virtual std::uint64_t next_u64() = 0; // thread-safe
};

// The operating system's generator (std::random_device: getrandom / /dev/urandom on Linux).
class SystemRandom final : public RandomSource {
public:
    std::uint64_t next_u64() override;

private:
    std::mutex mutex_;
};

// splitmix64 from a seed: deterministic, for tests.
class SeededRandom final : public RandomSource {
public:
    explicit SeededRandom(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next_u64() override;

private:
    std::mutex mutex_;
    std::uint64_t state_;
};

// 128 random bits as 32 lowercase hex digits.
std::string make_resume_token(RandomSource& random);
// 6 characters of proto::kRoomCodeAlphabet, uniformly (rejection sampling, no modulo bias).
std::string make_room_code(RandomSource& random);

} // namespace carrom::server
