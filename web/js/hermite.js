// Cubic Hermite interpolation of a position from its end points and end velocities
// (client/include/carrom/client/hermite.hpp). s = 0 gives p0, s = 1 gives p1, and the curve's
// derivative at the ends is v0 and v1. Board px, px/s, dt in s.
export function hermite(p0, v0, p1, v1, dt, s) {
  const s2 = s * s;
  const s3 = s2 * s;
  const h00 = 2 * s3 - 3 * s2 + 1;
  const h10 = s3 - 2 * s2 + s;
  const h01 = -2 * s3 + 3 * s2;
  const h11 = s3 - s2;
  return {
    x: p0.x * h00 + v0.x * (h10 * dt) + p1.x * h01 + v1.x * (h11 * dt),
    y: p0.y * h00 + v0.y * (h10 * dt) + p1.y * h01 + v1.y * (h11 * dt),
  };
}
