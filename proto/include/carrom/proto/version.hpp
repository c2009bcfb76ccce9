#pragma once
// The wire protocol's version. A client states it in hello; the server answers a different one
// with error "version_mismatch" and closes with kCloseVersionMismatch. Bump it on any change that
// an older peer would misread (a renamed or retyped field, a changed meaning). Adding an optional
// field does not need a bump: unknown fields are ignored by both sides.

namespace carrom::proto {

inline constexpr int kProtocolVersion = 1;

} // namespace carrom::proto
