#pragma once
// Where the Jacobian df/dx of the right-hand side can be non-zero, derived
// from the model's connectivity alone (no evaluation), and a colouring of its
// columns for compressed forward-mode AD.
//
// Structure of f for x = [q; u; z] (model/model.hpp):
//   dq_k/dt = u_k                      row q_k: column u_k only;
//   du/dt of body b                    rows u_b: the columns b's motion reads
//                                      (its free q and u) and, for every
//                                      element touching b, the columns of the
//                                      element's bodies and its internal
//                                      states z_e (the wheel-rail contact of a
//                                      wheelset reads its own motion only);
//   dz_e/dt of element e               rows z_e: the columns of e's bodies, z_e.
// A wheelset's spin angle is cyclic (kinematics/body_motion.hpp: the
// wheelset is axisymmetric and its elements attach to the non-spinning
// axle-box frame I), so no row depends on it; its spin *rate* does count.
// The track frames depend on time and speed only. The pattern is a superset
// of the true non-zeros; tests check it against the dense AD Jacobian on
// every case scene.
#include <railstab/core/scalar.hpp>
#include <railstab/model/model.hpp>

#include <vector>

namespace railstab {

// A sparsity pattern, row-wise: columns_of_row[r] lists the (sorted,
// distinct) columns where row r may be non-zero.
struct SparsityPattern {
  int rows = 0, cols = 0;
  std::vector<std::vector<int>> columns_of_row;

  bool contains(int r, int c) const;
  long nonzeros() const;
  double density() const { return rows * cols > 0 ? double(nonzeros()) / (double(rows) * cols) : 0.0; }
  int max_row_nonzeros() const;  // a lower bound of any column colouring
};

// The pattern of df/dx (state_size x state_size) from the model's structure.
SparsityPattern rhs_jacobian_pattern(const Model& model);

// The sub-pattern of the given rows and columns (indices into the full
// pattern), renumbered 0..rows.size()-1 and 0..columns.size()-1.
SparsityPattern sub_pattern(const SparsityPattern& full, const std::vector<int>& rows,
                            const std::vector<int>& columns);

// A column colouring: columns of one colour share no row of the pattern, so
// one AD direction seeded with all of them at once yields each of their
// entries separately (Curtis-Powell-Reid; a distance-2 colouring of the
// bipartite row-column graph).
struct ColumnColouring {
  std::vector<int> colour_of_column;
  int colours = 0;
};

// Greedy colouring: each column in turn takes the smallest colour not used
// by a column it shares a row with. Two orders are tried (natural, and
// largest number of neighbours first) and the one with fewer colours kept.
ColumnColouring colour_columns(const SparsityPattern& pattern);

// What a coloured Jacobian of some rows of f with respect to some columns of
// x needs, computed once per model (and choice of rows and columns): the
// pattern restricted to them, renumbered locally, and its column colouring
// (linear/jacobian.hpp: plan_rhs_jacobian, rhs_jacobian_ad).
struct RhsJacobianPlan {
  std::vector<int> rows, columns;  // into f and x
  SparsityPattern pattern;         // rows.size() x columns.size()
  ColumnColouring colouring;
  // AD evaluations per Jacobian: kAdChunk colours each.
  int passes() const { return (colouring.colours + kAdChunk - 1) / kAdChunk; }
};

// True if the colouring is valid for the pattern (no two columns of a colour
// share a row): the property the compressed Jacobian relies on.
bool is_valid_colouring(const SparsityPattern& pattern, const ColumnColouring& colouring);

}  // namespace railstab
