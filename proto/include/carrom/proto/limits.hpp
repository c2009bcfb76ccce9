#pragma once
// Field limits the decoder enforces. Game ranges that depend on the board (baseline x range,
// maximum power for the physics config) are checked by the server with the rules; these are the
// wire-level bounds every message must meet.

#include <cstddef>
#include <cstdint>

namespace carrom::proto {

inline constexpr std::size_t kMaxClientMessageBytes = 4096;   // client -> server text
inline constexpr std::size_t kMaxServerMessageBytes = 262144; // server -> client text (256 KiB)

inline constexpr std::size_t kMaxNameBytes = 24;      // UTF-8 bytes, no control characters
inline constexpr std::size_t kRoomCodeLength = 6;     // characters from kRoomCodeAlphabet
inline constexpr std::size_t kResumeTokenLength = 32; // lowercase hex, 128 bits
inline constexpr std::size_t kIdentityKeyLength = 64; // lowercase hex, 256 bits
inline constexpr std::size_t kMaxIdentityBytes = 128; // the wire's bound; see is_identity_key
inline constexpr std::size_t kMaxTextBytes = 200;     // error messages, foul descriptions
inline constexpr std::size_t kMaxUrlBytes = 2000;     // a redirect's URL
inline constexpr std::size_t kMaxSeats = 4;           // 2 (singles) or 4 (doubles)
inline constexpr std::size_t kMaxBodies = 64;         // bodies in one board or snapshot

// Unambiguous room code characters: no 0/O, 1/I/L.
inline constexpr char kRoomCodeAlphabet[] = "ABCDEFGHJKMNPQRSTUVWXYZ23456789";

inline constexpr std::int64_t kMaxTurn = 1000000;           // turn numbers 0..kMaxTurn
inline constexpr std::int64_t kMaxNonce = 9007199254740991; // 2^53 - 1, exact in every JSON reader
inline constexpr std::int64_t kMaxTimeMs = 9007199254740991;
inline constexpr double kMaxCoordinatePx = 10000.0; // |x|, |y| of any position
inline constexpr double kMaxSpeedPxS = 1.0e6;       // |vx|, |vy| of any velocity
inline constexpr double kMaxAngleRad = 100.0;       // |angle|
inline constexpr double kMaxPower = 1000.0;         // power in [0, kMaxPower]
inline constexpr double kMaxImpulse = 1.0e9;        //
inline constexpr double kMaxShotClockS = 600.0;     // 0 = no shot clock
inline constexpr int kMaxTargetPoints = 1000;       // 1..kMaxTargetPoints
inline constexpr int kMaxBoards = 99;               // 1..kMaxBoards
inline constexpr double kMaxMatchTimeS = 1.0e6;     // snapshot and event times

} // namespace carrom::proto
