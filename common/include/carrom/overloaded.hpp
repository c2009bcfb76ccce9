#pragma once
// Overloaded{lambdas...}: one callable with every lambda's operator(), for std::visit over a
// variant (one lambda per alternative).

namespace carrom {

template <class... F> struct Overloaded : F... { using F::operator()...; };
template <class... F> Overloaded(F...) -> Overloaded<F...>;

} // namespace carrom
