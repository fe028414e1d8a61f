// SPDX-License-Identifier: LGPL-2.1-or-later
// BLAS's triangular solve with several right-hand sides (xTRSM), which deal.II's
// lapack_templates.h does not wrap: the condensed solver's panel solve L21 = A21 L11⁻ᵀ
// works in place with it, where LAPACK's trtrs would need a transposed copy.
#pragma once

#include <deal.II/lac/lapack_support.h>

#include <type_traits>

extern "C"
{
  void
  strsm_(const char                    *side,
         const char                    *uplo,
         const char                    *transa,
         const char                    *diag,
         const dealii::types::blas_int *m,
         const dealii::types::blas_int *n,
         const float                   *alpha,
         const float                   *a,
         const dealii::types::blas_int *lda,
         float                         *b,
         const dealii::types::blas_int *ldb);
  void
  dtrsm_(const char                    *side,
         const char                    *uplo,
         const char                    *transa,
         const char                    *diag,
         const dealii::types::blas_int *m,
         const dealii::types::blas_int *n,
         const double                  *alpha,
         const double                  *a,
         const dealii::types::blas_int *lda,
         double                        *b,
         const dealii::types::blas_int *ldb);
}

namespace wearlink::fe::blas
{
  /** B := alpha B op(A)⁻¹ (side "R") or alpha op(A)⁻¹ B (side "L"), A triangular (float or double). */
  template <typename Number>
  inline void
  trsm(const char                    *side,
       const char                    *uplo,
       const char                    *transa,
       const char                    *diag,
       const dealii::types::blas_int *m,
       const dealii::types::blas_int *n,
       const Number                  *alpha,
       const Number                  *a,
       const dealii::types::blas_int *lda,
       Number                        *b,
       const dealii::types::blas_int *ldb)
  {
    static_assert(std::is_same_v<Number, float> || std::is_same_v<Number, double>);
    if constexpr (std::is_same_v<Number, float>)
      strsm_(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb);
    else
      dtrsm_(side, uplo, transa, diag, m, n, alpha, a, lda, b, ldb);
  }
} // namespace wearlink::fe::blas
