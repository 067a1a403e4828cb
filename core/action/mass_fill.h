// K ⊗ M (mass_band.h) into the banded Jacobian of a window's time nodes
// (reduced_system.h): each entry's block at a storage offset located once per
// operator and band, and for a march on a uniform grid, which assembles the
// same K ⊗ M at every refactorization, a band holding all the in-band
// products, added in one sweep or copied as the assembly's start.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <vector>

#include "core/action/mass_band.h"
#include "core/linalg/banded.h"

namespace vivp::action {

template <class Real, int d>
class MassFill {
 public:
  using Block = Eigen::Matrix<Real, d, d>;
  using Band = linalg::BandedMatrix<Real>;

  // Whether an assembly into `band` of K (its version) at 1/Δt = inv_dt with
  // mass M repeats the last one's K ⊗ M and finds its fill built: the band
  // can start as a copy of fill() (ReducedSystem::OverwriteJacobian).
  bool Repeats(const MassBand<Real>& k, const Block& mass, Real inv_dt,
               const Band& band) const {
    return ready_ && (mass.array() != Real(0)).any() &&
           Key(k, band) == fill_key_ && fill_key_ == offsets_key_ &&
           inv_dt == inv_dt_ && mass == mass_;
  }
  const Band& fill() const { return fill_; }

  // band += K ⊗ M with K = K̃·inv_dt; with `from_fill` (Repeats was true and
  // the band started as fill()) only the blocks outside the band. `offset`
  // (node row, node column) is the storage offset of that block
  // (BandedMatrix::BlockOffset, −1 outside the band); `add_outside` (node
  // row, node column, block) adds a block outside it.
  // The checks and index arithmetic of adding each block by its indices,
  // per entry and assembly, were 7 % of a uniform SBP84 march of the
  // anharmonic oscillator (callgrind); the blocks added one by one at their
  // offsets, 6 % (the fill adds the same products in the same places: the
  // same bits).
  template <class Offset, class AddOutside>
  void Add(const MassBand<Real>& k, const Block& mass, Real inv_dt, Band& band,
           bool from_fill, const Offset& offset,
           const AddOutside& add_outside) {
    const auto& entries = k.Entries();
    const std::array<long long, 4> key = Key(k, band);
    if (key != offsets_key_) {
      offsets_.resize(entries.size());
      for (std::size_t e = 0; e < entries.size(); ++e)
        offsets_[e] = offset(entries[e].row, entries[e].column);
      offsets_key_ = key;
    }
    const bool repeat = key == fill_key_ && inv_dt == inv_dt_ && mass == mass_;
    if (repeat) {
      if (!ready_) {
        fill_ = Band(band.size(), band.lower(), band.upper());
        outside_.clear();
        for (std::size_t e = 0; e < entries.size(); ++e)
          if (offsets_[e] >= 0)
            fill_.template AddBlockAt<d>(offsets_[e], inv_dt * entries[e].value,
                                         mass);
          else
            outside_.push_back(e);
        ready_ = true;
      }
      if (!from_fill) band.AddSameBand(fill_);
      for (const std::size_t e : outside_)
        add_outside(entries[e].row, entries[e].column,
                    Block(inv_dt * entries[e].value * mass));
      return;
    }
    fill_key_ = key;
    inv_dt_ = inv_dt;
    mass_ = mass;
    ready_ = false;
    for (std::size_t e = 0; e < entries.size(); ++e) {
      const Real scale = inv_dt * entries[e].value;
      if (offsets_[e] >= 0)
        band.template AddBlockAt<d>(offsets_[e], scale, mass);
      else
        add_outside(entries[e].row, entries[e].column, Block(scale * mass));
    }
  }

 private:
  static std::array<long long, 4> Key(const MassBand<Real>& k,
                                      const Band& band) {
    return {k.version(), band.size(), band.lower(), band.upper()};
  }

  // Where each entry of K goes, for the band of offsets_key_ (K's version,
  // n, kl, ku).
  std::vector<std::ptrdiff_t> offsets_;
  std::array<long long, 4> offsets_key_ = {-1, -1, -1, -1};
  // The in-band blocks of K ⊗ M at the step and mass of the last assembly,
  // once a second assembly repeated them.
  Band fill_;
  std::array<long long, 4> fill_key_ = {-1, -1, -1, -1};
  Real inv_dt_ = Real(0);
  Block mass_ = Block::Zero();
  bool ready_ = false;
  std::vector<std::size_t> outside_;  // entries outside the band
};

}  // namespace vivp::action
