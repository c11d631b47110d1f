// The visitor idiom for std::variant: overloaded lambdas, one per alternative.
#pragma once

namespace aapat {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
// Spelled out for compilers without aggregate deduction (clang before 17).
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace aapat
