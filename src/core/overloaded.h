#pragma once
// Overloaded: one visitor from several lambdas, for std::visit over a variant. Each
// alternative must be handled, so a new alternative is a compile error wherever it is not.
//
//   std::visit(Overloaded{[](const SphereShape& s) {...}, [](const BoxShape& b) {...}}, shape);

namespace prt {

template <typename... Fs>
struct Overloaded : Fs... {
  using Fs::operator()...;
};
template <typename... Fs>
Overloaded(Fs...) -> Overloaded<Fs...>;

}  // namespace prt
