#pragma once
/// First-order reproducing-kernel shape functions (paper Eq. 4) at the particles, with their
/// gradients. For particle I and each neighbour J (NeighbourList order):
///   phi_J(X_I) = b^T H(r) w_J(r),  r = X_I - X_J,  H(r) = [1, r / s],  b = M^-1 [1, 0, 0, 0]^T,
///   M(X_I) = sum_J w_J H H^T,
/// where s is particle I's mean support reach (scaling H keeps M well scaled and leaves phi
/// unchanged). They reproduce constant and linear fields exactly (sum_J phi_J = 1,
/// sum_J phi_J X_J = X_I, sum_J grad phi_J = 0, sum_J X_J (x) grad phi_J = I) wherever M is
/// invertible. Gradients: grad phi = grad w b^T H + w (grad b^T H + b^T grad H) with
/// grad_k b = -M^-1 (d_k M) b.
#include <Eigen/Core>

#include <vector>

#include "solver/spg/neighbours.hpp"

namespace mcdyna::solver::spg {

struct ShapeFunctions {
  std::vector<double> value;  ///< phi_J(X_I) per neighbour pair
  Eigen::Matrix3Xd gradient;  ///< d phi_J / dx at X_I per neighbour pair
  /// Only when asked for (ITB 1's strain gradient): per pair the second-derivative functions
  /// psi^ab_J(X_I), xx yy zz xy yz zx, of the quadratic reproducing kernel: with the same window
  /// w_J and the basis [1, z, z (x) z] (z in particle I's support coordinates),
  /// sum_J psi^ab_J(X_I) g(X_J) = d2 g / dx_a dx_b (X_I) for every quadratic g. They see the
  /// particle-to-particle modes whose first derivatives vanish at every particle. Entries a row
  /// cannot resolve (d2/dn2 across a surface) are zero.
  Eigen::Matrix<double, 6, Eigen::Dynamic> hessian;
};

/// Smallest eigenvalue / largest of the moment matrix (basis in support coordinates) below
/// which the particle's neighbourhood is degenerate (all neighbours on a plane or a line): the
/// linear basis cannot be reproduced there.
inline constexpr double kMinimumMomentRatio = 1.0e-8;

/// The same for a particle that has lost bonds (Eq. 36): its row is one-sided or thinned out,
/// and its gradients grow like 1 / sqrt(ratio). Regular lattice rows (DX 1.5, cubic box) sit at
/// 0.057 inside and 0.028 on a face, edge or corner; 1e-2 admits every such row and flags those
/// three times worse. Measured: the notch layer of the h = 0.5 bar, left with neighbours in its
/// own plane once its bonds to both halves broke, came in at 1e-6 to 1e-5 and its gradients blew
/// up (plastic strain 24 within 20 cycles); in the FDS plate (h = 0.15) damaged rows of the cap
/// the tip pushes out below the plate blew up at 1e-4 (74.9 us, force x6 per 10 cycles) and at
/// 1e-3 (50.5 us); at 1e-2 the run passes 100 us.
inline constexpr double kMinimumDamagedMomentRatio = 1.0e-2;

/// Eigenvalue of the quadratic moments' Schur complement (relative to its largest) below which
/// its direction counts as unresolved by the row (second-derivative functions,
/// ShapeFunctions::hessian): a surface row's two layers across the surface make z_n^2 a multiple
/// of z_n (eigenvalue ~1e-17 on a lattice, 1e-9 to 1e-4 once perturbed); resolved directions sit
/// at 1e-2 and above (measured on the coarse Taylor bar's rows, initial and renewed). A cut at
/// 1e-7 kept the perturbed ones: Sum |psi| h^2 of a renewed row reached 805 against 37 at the
/// start, and the bar inverted two cycles later; at 1e-3 the renewed rows stay under 110.
inline constexpr double kMinimumHessianRatio = 1.0e-3;

/// Computes the shape functions of every particle. Particles whose moment matrix is degenerate
/// get zero values and are listed in `degenerate` (ascending), for a diagnostic that names them.
/// `damaged` (size N or empty) flags the particles held to kMinimumDamagedMomentRatio.
/// `second_derivatives`: also ShapeFunctions::hessian.
ShapeFunctions shape_functions(const Eigen::Matrix3Xd& x, const Supports& support,
                               KernelShape shape, const NeighbourList& list,
                               std::vector<Index>& degenerate,
                               const std::vector<std::uint8_t>& damaged = {},
                               bool second_derivatives = false);

}  // namespace mcdyna::solver::spg
