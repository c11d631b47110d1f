// The visitor idiom for std::variant: overloaded lambdas, one per alternative.
#pragma once

namespace aapat {

template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};

}  // namespace aapat
