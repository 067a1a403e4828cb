// The Jacobian of a field system as a compressed sparse matrix whose pattern
// is fixed on the first assembly: later assemblies only overwrite values, each
// entry found by a binary search in its column (the field system feeds the
// same positions every time, field_system.h).
#pragma once

#include <Eigen/SparseCore>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace vivp::spacetime {

class PatternedMatrix {
 public:
  // fill(sink) calls sink.Add(row, col, value) for every entry.
  template <class Fill>
  void Assemble(int n, Fill&& fill) {
    if (!fixed_ || matrix_.rows() != n) {
      TripletSink sink;
      fill(sink);
      matrix_.resize(n, n);
      matrix_.setFromTriplets(sink.triplets.begin(), sink.triplets.end());
      matrix_.makeCompressed();
      fixed_ = true;
      ++patterns_;
      return;
    }
    std::fill(matrix_.valuePtr(), matrix_.valuePtr() + matrix_.nonZeros(), 0.0);
    LookupSink sink{&matrix_};
    fill(sink);
  }

  const Eigen::SparseMatrix<double>& matrix() const { return matrix_; }
  // How many times the pattern was built (1 after any number of assemblies
  // on one grid).
  int patterns() const { return patterns_; }
  void Reset() { fixed_ = false; }

 private:
  struct TripletSink {
    std::vector<Eigen::Triplet<double>> triplets;
    void Add(int r, int c, double v) { triplets.emplace_back(r, c, v); }
  };
  struct LookupSink {
    Eigen::SparseMatrix<double>* m;
    void Add(int r, int c, double v) {
      const int* begin = m->innerIndexPtr() + m->outerIndexPtr()[c];
      const int* end = m->innerIndexPtr() + m->outerIndexPtr()[c + 1];
      const int* at = std::lower_bound(begin, end, r);
      if (at == end || *at != r)
        throw std::logic_error("PatternedMatrix: entry (" + std::to_string(r) +
                               ", " + std::to_string(c) +
                               ") outside the first assembly's pattern");
      m->valuePtr()[at - m->innerIndexPtr()] += v;
    }
  };

  Eigen::SparseMatrix<double> matrix_;
  bool fixed_ = false;
  int patterns_ = 0;
};

}  // namespace vivp::spacetime
