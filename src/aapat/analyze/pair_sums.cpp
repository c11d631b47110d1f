#include "aapat/analyze/pair_sums.h"

#include <algorithm>

namespace aapat {
namespace {

// A Fenwick tree over ranks: how many values were added below a rank, and
// their sum (count and sum side by side: one cache line per level).
class RankSums {
 public:
  explicit RankSums(size_t n) : nodes_(n + 1) {}
  void add(size_t rank, DoubleDouble v) {
    for (size_t i = rank + 1; i < nodes_.size(); i += i & (~i + 1)) {
      nodes_[i].count += 1;
      nodes_[i].sum += v;
    }
  }
  // The values added at ranks < rank: how many, and their sum.
  std::pair<double, DoubleDouble> below(size_t rank) const {
    double c = 0;
    DoubleDouble s;
    for (size_t i = rank; i > 0; i -= i & (~i + 1)) {
      c += nodes_[i].count;
      s += nodes_[i].sum;
    }
    return {c, s};
  }

 private:
  struct Node {
    DoubleDouble sum;
    double count = 0;  // exact: counts stay below 2^53
  };
  std::vector<Node> nodes_;
};

}  // namespace

std::vector<size_t> ascending_order(std::span<const DoubleDouble> v) {
  // The keys sorted with their indices, not the indices through the keys:
  // at millions of points the indirect comparisons miss the cache.
  struct Key {
    DoubleDouble v;
    size_t index;
  };
  std::vector<Key> keys(v.size());
  for (size_t i = 0; i < v.size(); ++i) keys[i] = {v[i], i};
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return a.v < b.v || (!(b.v < a.v) && a.index < b.index);
  });
  std::vector<size_t> order(v.size());
  for (size_t i = 0; i < v.size(); ++i) order[i] = keys[i].index;
  return order;
}

void moments(std::span<const DoubleDouble> a, std::span<const DoubleDouble> b, Moments& out) {
  for (auto& row : out)
    for (auto& m : row) m = DoubleDouble();
  for (size_t i = 0; i < a.size(); ++i) {
    const DoubleDouble ap[3] = {1.0, a[i], a[i] * a[i]}, bq[3] = {1.0, b[i], b[i] * b[i]};
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) out[p][q] += ap[p] * bq[q];
  }
}

DoubleDouble polynomial_min_sum(const PairPolynomial& q, std::span<const DoubleDouble> a,
                                std::span<const DoubleDouble> b, std::span<const size_t> order) {
  // In ascending b, point j = order[k] meets the points before it with
  // min = b_i and those from k on with min = b_j (ties: b_i = b_j either way):
  //   sum_i a_i^p min(b_i, b_j) = (sum before k of a_i^p b_i) + b_j (sum from k of a_i^p),
  // then weighted by q[p][r] a_j^r. One pass for every monomial.
  DoubleDouble suffix[3], prefix[3];
  for (const size_t i : order) {
    suffix[0] += 1.0;
    suffix[1] += a[i];
    suffix[2] += a[i] * a[i];
  }
  DoubleDouble total;
  for (const size_t j : order) {
    const DoubleDouble power[3] = {1.0, a[j], a[j] * a[j]};
    DoubleDouble inner[3];  // sum_i a_i^p min(b_i, b_j)
    for (int p = 0; p < 3; ++p) inner[p] = prefix[p] + b[j] * suffix[p];
    for (int r = 0; r < 3; ++r) {
      DoubleDouble weighted;
      for (int p = 0; p < 3; ++p)
        if (q[p][r] != 0) weighted += DoubleDouble(q[p][r]) * inner[p];
      total += power[r] * weighted;
    }
    for (int p = 0; p < 3; ++p) {
      prefix[p] += power[p] * b[j];
      suffix[p] = suffix[p] - power[p];
    }
  }
  return total;
}

DoubleDouble min_min_sum(std::span<const DoubleDouble> a, std::span<const DoubleDouble> b,
                         std::span<const size_t> by_a, std::span<const size_t> by_b) {
  // In descending a, point j meets each earlier point i (a_i >= a_j) with
  // a_j min(b_i, b_j), and over those i the min sums to (sum of b_i below
  // b_j) + b_j (how many are not below): two queries of a Fenwick tree over
  // b's ranks. Each unordered pair once, doubled, plus the diagonal.
  const size_t n = a.size();
  std::vector<size_t> rank(n);
  for (size_t r = 0; r < n; ++r) rank[by_b[r]] = r;
  RankSums sums(n);
  DoubleDouble off_diagonal, diagonal;
  for (size_t k = n; k-- > 0;) {
    const size_t j = by_a[k];
    const auto [below, below_sum] = sums.below(rank[j]);
    const double not_below = static_cast<double>(n - 1 - k) - below;
    off_diagonal += a[j] * (below_sum + b[j] * DoubleDouble(not_below));
    diagonal += a[j] * b[j];
    sums.add(rank[j], b[j]);
  }
  return off_diagonal * 2.0 + diagonal;
}

}  // namespace aapat
