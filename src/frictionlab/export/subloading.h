/*
 * subloading.h -- the subloading-friction law (Hashiguchi & Ozaki 2008) for one contact
 * point: a C99 translation of frictionlab.subloading.kernels._point, operation for
 * operation, so that it returns the same numbers as frictionlab's compiled kernel.
 *
 * No dependency beyond the C library (libm, fenv). Units are SI; the traction is
 * (f_t1, f_t2, f_n) in the co-rotating contact frame with f_n > 0 in compression and the
 * slip increment (du_t1, du_t2, du_n) with du_n the approach (positive closes).
 *
 * Any change of frictionlab/subloading/{kernels,evolution,surfaces}.py must be mirrored
 * here: tests/export/test_c_core.py compares the two on random inputs, bit for bit.
 */
#ifndef FRICTIONLAB_SUBLOADING_H
#define FRICTIONLAB_SUBLOADING_H

#ifdef __cplusplus
extern "C" {
#endif

/* status codes (frictionlab.subloading.Status) */
#define SL_STICK 0
#define SL_SLIP 1
#define SL_OPEN 2
#define SL_FAILED 3

/* surface families (frictionlab.subloading.surfaces) */
#define SL_COULOMB 0
#define SL_CAM_CLAY 1
#define SL_MODIFIED_CAM_CLAY 2
#define SL_TEAR 3
#define SL_PARABOLA 4

/* options */
#define SL_U_COT 0 /* U = u cot(pi R/2), Eq 28 */
#define SL_U_LN 1  /* U = -u ln R, Eq 30 */
#define SL_EXPONENTIAL 0
#define SL_BACKWARD_EULER 1
#define SL_ONE_MINUS 0 /* recovery xi (1 - F/F_s)^n */
#define SL_RATIO 1     /* recovery xi (F_s/F - 1)^n */

/* columns of the parameter row (frictionlab.subloading.kernels.P_*) */
#define SL_P_ALPHA_N 0 /* normal elastic modulus [Pa/m] */
#define SL_P_ALPHA_T 1 /* tangential elastic modulus [Pa/m] */
#define SL_P_FS 2      /* static size: mu_s (cone) or F_s [Pa] */
#define SL_P_FK 3      /* kinetic size: mu_k (cone) or F_k [Pa] */
#define SL_P_U 4       /* u of U(R) [1/m] */
#define SL_P_KAPPA 5   /* softening rate [F units per m] */
#define SL_P_XI 6      /* recovery rate [F units per s] */
#define SL_P_M 7       /* softening exponent */
#define SL_P_N 8       /* recovery exponent */
#define SL_P_BETA1 9   /* rotation beta_1 (contact frame) */
#define SL_P_BETA2 10  /* rotation beta_2 */
#define SL_P_A1 11     /* axis factor A_1 = C_1 (cone) or C_1 M (closed) */
#define SL_P_A2 12     /* axis factor A_2 */
#define SL_P_ANGLE 13  /* orthotropy angle [rad] */
#define SL_N_PARAMS 14

typedef struct {
    int surface;      /* SL_COULOMB ... SL_PARABOLA */
    double tear_k;    /* exponent k of the tear family */
    int u_law;        /* SL_U_COT or SL_U_LN */
    int integrator;   /* SL_EXPONENTIAL or SL_BACKWARD_EULER */
    int recovery;     /* SL_ONE_MINUS or SL_RATIO */
    int open_frozen;  /* 1: F frozen while open, 0: F recovers */
    int want_tangent; /* 0: the tangent is left zero */
} sl_options;

typedef struct {
    int status;         /* SL_STICK, SL_SLIP, SL_OPEN or SL_FAILED */
    int iterations;     /* Newton iterations of the local solve */
    double traction[3]; /* (f_t1, f_t2, f_n) at the end of the increment [Pa] */
    double F, R, gap;   /* new state: size, normal-yield ratio, opening [m] */
    double dlam;        /* plastic slip |Delta u^p| [m] */
    double vp[2];       /* plastic slip increment (tangential) [m] */
    double diss;        /* f . Delta u^p [J/m^2] */
    double tangent[3][3]; /* d traction_i / d slip_j [Pa/m], row i, column j */
} sl_result;

/* One increment of one point. p: the parameter row (SL_P_*); (ca, sa): cos and sin of
 * p[SL_P_ANGLE]; traction, F_old, R_old, gap_old: the state at the start; slip: the slip
 * increment; dt: the time increment [s]. A failed point (SL_FAILED) keeps its old state
 * and gets the elastic tangent. Returns the status. */
int sl_point(const double *p, double ca, double sa, const double *traction, double F_old,
             double R_old, double gap_old, const double *slip, double dt,
             const sl_options *opt, sl_result *out);

/* n points (C order arrays as frictionlab.subloading.kernels.step_points); P has 1 or n
 * rows, dt 1 or n entries; out_tangent may be NULL when no tangent is wanted. */
void sl_step_points(long n, const double *traction, const double *F_old, const double *R_old,
                    const double *gap_old, const double *slip, const double *dt, long n_dt,
                    const double *P, long n_rows, const sl_options *opt, double *out_traction,
                    double *out_F, double *out_R, double *out_gap, double *out_dlam,
                    double *out_vp, double *out_diss, double *out_tangent, int *out_status,
                    int *out_iterations);

#ifdef __cplusplus
}
#endif
#endif
