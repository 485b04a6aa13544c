#pragma once
// What a 2-D effective mass is made of (Catto GDC 2011, "3:2"): K = J M^-1 J^T split into each body's
// translational and rotational term, so a designer sees which body and which lever sets the mass.

#include "softtune/effective_mass.h"

namespace softtune {

/// The four terms of a 2-D K, each body's translational 1/m and rotational (r x n)^2 / I (angular: 1/I,
/// translational 0), in K's units. They sum to inverse_effective_mass(c), which is computed from them.
struct InverseMassTerms {
  double a_translational = 0.0, a_rotational = 0.0;
  double b_translational = 0.0, b_rotational = 0.0;
};
InverseMassTerms inverse_effective_mass_terms(const Constraint2D& c);

}  // namespace softtune
