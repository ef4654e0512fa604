/*
 * subloading.c -- the subloading-friction law for one contact point (see subloading.h).
 *
 * A line-by-line translation of frictionlab/subloading/{surfaces,evolution,kernels}.py;
 * the function names and the order of every floating-point operation are kept, so that
 * the results are bit-identical to the numba kernel (compiled without contraction into
 * fused multiply-adds: -ffp-contract=off). min/max follow Python's rule (the first
 * argument unless the second is strictly smaller/larger).
 *
 * A division by zero (numba's ZeroDivisionError, which fails the whole batch in Python)
 * fails the point here: the floating-point flag is tested after the update, and so is
 * every output (a 0/0 or inf/0, which raises no such flag, leaves a NaN or infinity).
 */
#include "subloading.h"

#include <fenv.h>
#include <math.h>

#define HALF_PI (0.5 * 3.14159265358979323846)
#define INV_HALF_PI (2.0 / 3.14159265358979323846)
#define PI 3.14159265358979323846

#define RTOL_RESIDUAL 1e-13
#define RTOL_ACCEPT 1e-10
#define SEPARATION_RTOL 1e-12
#define PATH_SAMPLES 8
#define MAX_ITERATIONS 100
#define MODEL_ITERATIONS 4
#define MODEL_RTOL 1e-3
#define DOMAIN_MODEL_ITERATIONS 16
#define RTOL_EXACT 1e-14

static inline double pmax(double a, double b) { return b > a ? b : a; }
static inline double pmin(double a, double b) { return b < a ? b : a; }

/* log, log1p and pow with numba's values at their poles but without the division-by-zero
 * flag, which here marks a true division by zero only */
static inline double xlog(double x) { return x == 0.0 ? -INFINITY : log(x); }
static inline double xlog1p(double x) { return x == -1.0 ? -INFINITY : log1p(x); }
static inline double xpow(double x, double y)
{
    if (x == 0.0 && y < 0.0) return (signbit(x) && fmod(y, 2.0) == -1.0) ? -INFINITY : INFINITY;
    return pow(x, y);
}

/* ================================================================== surfaces.py */
static void g_value(int code, double tear_k, double chi, double *g, double *dg)
{
    if (code == SL_CAM_CLAY) {
        double e = exp(chi);
        *g = e;
        *dg = e;
        return;
    }
    if (code == SL_MODIFIED_CAM_CLAY) {
        *g = 1.0 + chi * chi;
        *dg = 2.0 * chi;
        return;
    }
    if (code == SL_TEAR) {
        double a = 1.0 / (2.0 * tear_k + 1.0);
        double base = 1.0 - a * chi * chi;
        if (base <= 0.0) {
            *g = INFINITY;
            *dg = INFINITY;
            return;
        }
        double gg = xpow(base, -tear_k);
        *g = gg;
        *dg = 2.0 * a * tear_k * chi * gg / base;
        return;
    }
    if (code == SL_PARABOLA) {
        if (chi >= 2.0) {
            *g = INFINITY;
            *dg = INFINITY;
            return;
        }
        double d = 2.0 - chi;
        *g = 2.0 / d;
        *dg = 2.0 / (d * d);
        return;
    }
    *g = NAN;
    *dg = NAN;
}

/* Phi(w, f_n) and (Phi_w, Phi_fn) */
static void potential(int code, double tear_k, double w, double fn, double *phi, double *phi_w,
                      double *phi_fn)
{
    if (code == SL_COULOMB) {
        double inv = 1.0 / fn;
        double ph = w * inv;
        *phi = ph;
        *phi_w = inv;
        *phi_fn = -ph * inv;
        return;
    }
    double chi = w / fn;
    double g, dg;
    g_value(code, tear_k, chi, &g, &dg);
    if (isinf(g)) {
        *phi = INFINITY;
        *phi_w = INFINITY;
        *phi_fn = -INFINITY;
        return;
    }
    *phi = fn * g;
    *phi_w = dg;
    *phi_fn = g - chi * dg;
}

/* ================================================================== evolution.py: R */
static void ratio_start(int law, double R0, double *y0, double *s0)
{
    if (law == SL_U_COT) {
        *y0 = cos(HALF_PI * R0);
        *s0 = sin(HALF_PI * R0);
        return;
    }
    *y0 = 0.0;
    *s0 = 0.0;
}

static void ratio_from(int law, double u, double y0, double s0, double R0, double dlam,
                       double *R, double *slope)
{
    if (law == SL_U_COT) {
        double em = expm1(-HALF_PI * u * dlam);
        double y = y0 * (1.0 + em);
        double s2 = s0 * s0 - y0 * y0 * (em * (2.0 + em));
        double s = s2 > 0.0 ? sqrt(s2) : 0.0;
        *R = atan2(s, y) * INV_HALF_PI;
        *slope = s > 0.0 ? u * y / s : INFINITY;
        return;
    }
    if (dlam <= 0.0) {
        if (R0 <= 0.0) {
            *R = 0.0;
            *slope = INFINITY;
            return;
        }
        *R = R0;
        *slope = -u * xlog(R0);
        return;
    }
    double c = u * dlam;
    double x = R0 <= 1.0 ? 0.0 : xlog(R0);
    for (int it = 0; it < 200; it++) {
        double ex = exp(x);
        double h = ex - R0 + c * x;
        double step = h / (ex + c);
        x -= step;
        if (fabs(step) <= 1e-16 * pmax(1.0, fabs(x))) break;
    }
    double Rv = exp(x);
    *R = Rv;
    *slope = -u * x / (1.0 + c / Rv);
}

static double ratio_sensitivity(int law, double u, double y0, double s0, double dlam, double R)
{
    if (law == SL_U_COT) {
        double em = expm1(-HALF_PI * u * dlam);
        double s2 = s0 * s0 - y0 * y0 * (em * (2.0 + em));
        double s = s2 > 0.0 ? sqrt(s2) : 0.0;
        return s > 0.0 ? (1.0 + em) * s0 / s : 1.0;
    }
    if (dlam <= 0.0) return 1.0;
    return 1.0 / (1.0 + u * dlam / R);
}

/* ================================================================== evolution.py: F */
static void recovery_rate(double F, double Fs, double n, int form, double *psi, double *dpsi)
{
    if (form == SL_ONE_MINUS) {
        double x = 1.0 - F / Fs;
        if (x <= 0.0) {
            *psi = 0.0;
            *dpsi = n == 1.0 ? -1.0 / Fs : (n > 1.0 ? 0.0 : -INFINITY);
            return;
        }
        if (n == 1.0) {
            *psi = x;
            *dpsi = -1.0 / Fs;
            return;
        }
        *psi = xpow(x, n);
        *dpsi = -n * xpow(x, n - 1.0) / Fs;
        return;
    }
    double x = Fs / F - 1.0;
    if (x <= 0.0) {
        *psi = 0.0;
        *dpsi = n == 1.0 ? -Fs / (F * F) : (n > 1.0 ? 0.0 : -INFINITY);
        return;
    }
    if (n == 1.0) {
        *psi = x;
        *dpsi = -Fs / (F * F);
        return;
    }
    *psi = xpow(x, n);
    *dpsi = -n * xpow(x, n - 1.0) * Fs / (F * F);
}

static void softening_rate(double F, double Fk, double m, double *phi, double *dphi)
{
    double x = F / Fk - 1.0;
    if (x <= 0.0) {
        *phi = 0.0;
        *dphi = m == 1.0 ? 1.0 / Fk : (m > 1.0 ? 0.0 : INFINITY);
        return;
    }
    if (m == 1.0) {
        *phi = x;
        *dphi = 1.0 / Fk;
        return;
    }
    *phi = xpow(x, m);
    *dphi = m * xpow(x, m - 1.0) / Fk;
}

static double recover_exactly(double F0, double Fs, double xi, double n, double dt)
{
    if (xi == 0.0 || dt == 0.0) return F0;
    double x0 = pmax(1.0 - F0 / Fs, 0.0);
    double x;
    if (n == 1.0) {
        x = x0 * exp(-xi * dt / Fs);
    } else if (n > 1.0) {
        x = x0 == 0.0 ? 0.0
                      : xpow(xpow(x0, 1.0 - n) + (n - 1.0) * xi * dt / Fs, -1.0 / (n - 1.0));
    } else {
        double base = xpow(x0, 1.0 - n) - (1.0 - n) * xi * dt / Fs;
        x = base > 0.0 ? xpow(base, 1.0 / (1.0 - n)) : 0.0;
    }
    return Fs * (1.0 - x);
}

static void soften_exactly(double F1, double Fk, double kappa, double m, double dlam, double *F,
                           double *dF)
{
    double x1 = pmax(F1 / Fk - 1.0, 0.0);
    if (kappa == 0.0 || x1 == 0.0) {
        *F = F1;
        *dF = x1 == 0.0 ? 0.0 : -kappa * xpow(x1, m);
        return;
    }
    double c = kappa * dlam / Fk;
    double x;
    if (m == 1.0) {
        x = x1 * exp(-c);
    } else if (m > 1.0) {
        x = xpow(xpow(x1, 1.0 - m) + (m - 1.0) * c, -1.0 / (m - 1.0));
    } else {
        double base = xpow(x1, 1.0 - m) - (1.0 - m) * c;
        x = base > 0.0 ? xpow(base, 1.0 / (1.0 - m)) : 0.0;
    }
    *F = Fk * (1.0 + x);
    *dF = -kappa * xpow(x, m);
}

static void backward_euler(double F0, double Fs, double Fk, double kappa, double xi, double m,
                           double n, double dlam, double dt, int form, double *Fout,
                           double *dFout)
{
    double kl = kappa * dlam;
    double xt = xi * dt;
    double F, phi, dphi, psi, dpsi;
    if (m == 1.0 && n == 1.0 && form == SL_ONE_MINUS) {
        F = (F0 + kl + xt) / (1.0 + kl / Fk + xt / Fs);
    } else {
        double lo = Fk, hi = Fs;
        F = pmin(pmax(F0, lo), hi);
        for (int it = 0; it < 200; it++) {
            softening_rate(F, Fk, m, &phi, &dphi);
            recovery_rate(F, Fs, n, form, &psi, &dpsi);
            double h = F - F0 + kl * phi - xt * psi;
            if (h > 0.0)
                hi = F;
            else
                lo = F;
            double dh = 1.0 + kl * dphi - xt * dpsi;
            double Fn = (isfinite(dh) && dh > 0.0) ? F - h / dh : 0.5 * (lo + hi);
            if (!(lo < Fn && Fn < hi)) Fn = 0.5 * (lo + hi);
            if (fabs(Fn - F) <= 1e-15 * Fs || hi - lo <= 1e-15 * Fs) {
                F = Fn;
                break;
            }
            F = Fn;
        }
    }
    softening_rate(F, Fk, m, &phi, &dphi);
    recovery_rate(F, Fs, n, form, &psi, &dpsi);
    double dh = 1.0 + kl * dphi - xt * dpsi;
    *Fout = F;
    *dFout = !isfinite(dh) ? 0.0 : -kappa * phi / dh;
}

static const double GK_X[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
static const double GK_WK[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
static const double GK_WG[8] = {0.0,
                                0.129484966168869693270611432679082,
                                0.0,
                                0.279705391489276667901467771423780,
                                0.0,
                                0.381830050505118944950369775488975,
                                0.0,
                                0.417959183673469387755102040816327};

static double drift(double F, double Fs, double Fk, double a, double b, double m, double n,
                    int form)
{
    double psi, dpsi, phi, dphi;
    recovery_rate(F, Fs, n, form, &psi, &dpsi);
    softening_rate(F, Fk, m, &phi, &dphi);
    return b * psi - a * phi;
}

static double power_change(double base, double delta, double p)
{
    if (base <= 0.0) return xpow(pmax(delta, 0.0), p);
    return xpow(base, p) * expm1(p * xlog1p(delta / base));
}

static void integrand(double z, double F_hi, double F_lo, double D0, double sigma, double Fs,
                      double Fk, double a, double b, double m, double n, int form, double *r0,
                      double *r1)
{
    double d = D0 * exp(z);
    double F = F_hi + (F_lo - sigma * d);
    double F_inf = F_hi + F_lo;
    double d_soft = power_change(((F_hi - Fk) + F_lo) / Fk, -sigma * d / Fk, m);
    double d_rec;
    if (form == SL_ONE_MINUS)
        d_rec = power_change(((Fs - F_hi) - F_lo) / Fs, sigma * d / Fs, n);
    else
        d_rec = power_change(((Fs - F_hi) - F_lo) / F_inf, sigma * d * Fs / (F_inf * F), n);
    double G = fabs(b * d_rec - a * d_soft);
    if (!(G > 0.0)) {
        *r0 = INFINITY;
        *r1 = INFINITY;
        return;
    }
    double phi, dphi;
    softening_rate(F, Fk, m, &phi, &dphi);
    double ratio = d / G;
    *r0 = ratio;
    *r1 = phi * ratio / G;
}

static void gk15(double lo, double hi, double F_hi, double F_lo, double D0, double sigma,
                 double Fs, double Fk, double a, double b, double m, double n, int form,
                 double out[4])
{
    double c = 0.5 * (lo + hi);
    double h = 0.5 * (hi - lo);
    double k0 = 0.0, g0 = 0.0, k1 = 0.0, g1 = 0.0;
    for (int j = 0; j < 8; j++) {
        double v0, v1;
        if (j == 7) {
            integrand(c, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form, &v0, &v1);
        } else {
            double x = h * GK_X[j];
            double p0, p1, q0, q1;
            integrand(c - x, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form, &p0, &p1);
            integrand(c + x, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form, &q0, &q1);
            v0 = p0 + q0;
            v1 = p1 + q1;
        }
        k0 += GK_WK[j] * v0;
        g0 += GK_WG[j] * v0;
        k1 += GK_WK[j] * v1;
        g1 += GK_WG[j] * v1;
    }
    out[0] = k0 * h;
    out[1] = k1 * h;
    out[2] = fabs(k0 - g0) * h;
    out[3] = fabs(k1 - g1) * h;
}

static void quad(double z_lo, double z_hi, double F_hi, double F_lo, double D0, double sigma,
                 double Fs, double Fk, double a, double b, double m, double n, int form,
                 double tol, double *t0, double *t1)
{
    if (z_hi <= z_lo) {
        *t0 = 0.0;
        *t1 = 0.0;
        return;
    }
    double total0 = 0.0, total1 = 0.0;
    long pieces = (long)ceil((z_hi - z_lo) / 2.0);
    double stack_lo[64], stack_hi[64];
    for (long p = 0; p < pieces; p++) {
        stack_lo[0] = z_lo + (z_hi - z_lo) * (double)p / (double)pieces;
        stack_hi[0] =
            p == pieces - 1 ? z_hi : z_lo + (z_hi - z_lo) * (double)(p + 1) / (double)pieces;
        int top = 1;
        int count = 0;
        while (top > 0) {
            top -= 1;
            double lo = stack_lo[top];
            double hi = stack_hi[top];
            double k[4];
            gk15(lo, hi, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form, k);
            count += 1;
            int ok = k[2] <= tol * k[0] && k[3] <= tol * k[1];
            if (ok || top >= 62 || count >= 200 || hi - lo <= 1e-9) {
                total0 += k[0];
                total1 += k[1];
            } else {
                double c = 0.5 * (lo + hi);
                stack_lo[top] = lo;
                stack_hi[top] = c;
                stack_lo[top + 1] = c;
                stack_hi[top + 1] = hi;
                top += 2;
            }
        }
    }
    *t0 = total0;
    *t1 = total1;
}

static double fixed_point(double Fs, double Fk, double a, double b, double m, double n, int form)
{
    double lo = Fk, hi = Fs;
    if (drift(hi, Fs, Fk, a, b, m, n, form) >= 0.0) return hi;
    if (drift(lo, Fs, Fk, a, b, m, n, form) <= 0.0) return lo;
    double F = 0.5 * (lo + hi);
    for (int it = 0; it < 200; it++) {
        double G = drift(F, Fs, Fk, a, b, m, n, form);
        if (G > 0.0)
            lo = F;
        else if (G < 0.0)
            hi = F;
        else
            return F;
        double psi, dpsi, phi, dphi;
        recovery_rate(F, Fs, n, form, &psi, &dpsi);
        softening_rate(F, Fk, m, &phi, &dphi);
        double dG = b * dpsi - a * dphi;
        double F_new = (isfinite(dG) && dG < 0.0) ? F - G / dG : 0.5 * (lo + hi);
        if (!(lo < F_new && F_new < hi)) F_new = 0.5 * (lo + hi);
        if (F_new == F || hi - lo <= 4.4e-16 * hi) return F_new;
        F = F_new;
    }
    return F;
}

static double attractor_sensitivity(double F_inf, double Fs, double Fk, double a, double b,
                                    double m, double n, int form)
{
    double phi, dphi, psi, dpsi;
    softening_rate(F_inf, Fk, m, &phi, &dphi);
    recovery_rate(F_inf, Fs, n, form, &psi, &dpsi);
    double dG = b * dpsi - a * dphi;
    if (!isfinite(dG) || dG >= 0.0) return 0.0;
    return phi / dG;
}

static void constant_rate_size(double F0, double Fs, double Fk, double a, double b, double m,
                               double n, int form, double *Fout, double *dFda)
{
    F0 = pmin(pmax(F0, Fk), Fs);
    if (a == 0.0 && b == 0.0) {
        *Fout = F0;
        *dFda = 0.0;
        return;
    }
    double F_hi = fixed_point(Fs, Fk, a, b, m, n, form);
    double F_lo = 0.0;
    if (Fk < F_hi && F_hi < Fs) {
        double psi, dpsi, phi, dphi;
        recovery_rate(F_hi, Fs, n, form, &psi, &dpsi);
        softening_rate(F_hi, Fk, m, &phi, &dphi);
        double dG = b * dpsi - a * dphi;
        if (isfinite(dG) && dG < 0.0) {
            F_lo = -drift(F_hi, Fs, Fk, a, b, m, n, form) / dG;
            if (!(fabs(F_lo) <= 4.4e-16 * F_hi)) F_lo = 0.0;
        }
    }
    double F_inf = F_hi + F_lo;
    double D0 = fabs((F0 - F_hi) - F_lo);
    double z_min = D0 > 0.0 ? xlog(pmax(4.4e-16 * F_inf, 1e-300) / D0) : 0.0;
    if (z_min >= 0.0) {
        *Fout = F_inf;
        *dFda = attractor_sensitivity(F_inf, Fs, Fk, a, b, m, n, form);
        return;
    }
    double sigma = (F_hi - F0) + F_lo > 0.0 ? 1.0 : -1.0;
    double z = 0.0, tau = 0.0, sens = 0.0;
    double lo = z_min, hi = 0.0;
    int lo_known = 0;
    for (int it = 0; it < 100; it++) {
        double h, h1_unused;
        integrand(z, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form, &h, &h1_unused);
        double e = 1.0 - tau;
        if (fabs(e) <= RTOL_EXACT) break;
        double z_new = (h > 0.0 && isfinite(h)) ? z - e / h : 0.5 * (lo + hi);
        if (!(lo < z_new && z_new < hi))
            z_new = lo_known ? 0.5 * (lo + hi) : pmax(pmax(z_min, 0.5 * (lo + hi)), z_new);
        if (z_new <= z_min) z_new = z_min;
        double d_tau, d_sens;
        if (z_new < z) {
            quad(z_new, z, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form, RTOL_EXACT, &d_tau,
                 &d_sens);
            tau += d_tau;
            sens += d_sens;
        } else {
            quad(z, z_new, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form, RTOL_EXACT, &d_tau,
                 &d_sens);
            tau -= d_tau;
            sens -= d_sens;
        }
        z = z_new;
        if (tau >= 1.0) {
            lo = z;
            lo_known = 1;
        } else {
            hi = z;
            if (z <= z_min) {
                *Fout = F_inf;
                *dFda = attractor_sensitivity(F_inf, Fs, Fk, a, b, m, n, form);
                return;
            }
        }
        if (hi - lo <= 1e-15 * pmax(1.0, fabs(z)) && lo_known) break;
    }
    double d = D0 * exp(z);
    double F1 = F_hi + (F_lo - sigma * d);
    double h1, h1b;
    integrand(z, F_hi, F_lo, D0, sigma, Fs, Fk, a, b, m, n, form, &h1, &h1b);
    double g_end = (h1 > 0.0 && isfinite(h1)) ? d / h1 : 0.0;
    F1 = pmin(pmax(F1, Fk), Fs);
    double psi, dpsi, phi, dphi;
    recovery_rate(F1, Fs, n, form, &psi, &dpsi);
    softening_rate(F1, Fk, m, &phi, &dphi);
    double scale = b * psi + a * phi;
    if (g_end <= 1e-9 * scale) {
        *Fout = F1;
        *dFda = attractor_sensitivity(F_inf, Fs, Fk, a, b, m, n, form);
        return;
    }
    *Fout = F1;
    *dFda = -g_end * sens;
}

static double recovered_size(double F0, double Fs, double Fk, double xi, double m, double n,
                             double dt, int integrator, int form)
{
    if (integrator == SL_BACKWARD_EULER) {
        double F, dF;
        backward_euler(F0, Fs, Fk, 0.0, xi, m, n, 0.0, dt, form, &F, &dF);
        return F;
    }
    F0 = pmin(pmax(F0, Fk), Fs);
    if (xi == 0.0 || dt == 0.0) return F0;
    if (form == SL_ONE_MINUS) return recover_exactly(F0, Fs, xi, n, dt);
    if (xi * dt * xpow(Fs / Fk - 1.0, n) <= 1e-17 * Fk) return F0;
    double F, dF;
    constant_rate_size(F0, Fs, Fk, 0.0, xi * dt, m, n, form, &F, &dF);
    return F;
}

static void size_after(double F0, double Fs, double Fk, double kappa, double xi, double m,
                       double n, double dlam, double dt, int integrator, int form, double *Fout,
                       double *dFout)
{
    if (integrator == SL_BACKWARD_EULER) {
        backward_euler(F0, Fs, Fk, kappa, xi, m, n, dlam, dt, form, Fout, dFout);
        return;
    }
    if (m == 1.0 && n == 1.0 && form == SL_ONE_MINUS) {
        double a_soft = (kappa / Fk) * dlam;
        double a = a_soft + xi * dt / Fs;
        if (a == 0.0) {
            *Fout = F0;
            *dFout = -kappa * (F0 / Fk - 1.0);
            return;
        }
        double ia = 1.0 / a;
        double F_inf = (kappa * dlam + xi * dt) * ia;
        double em = expm1(-a);
        double e = 1.0 + em;
        double one_minus_e_over_a = -em * ia;
        double F = F_inf + (F0 - F_inf) * e;
        double dF =
            kappa * (1.0 - F_inf * (1.0 / Fk)) * one_minus_e_over_a + (F_inf - F0) * e * (kappa / Fk);
        *Fout = pmin(pmax(F, Fk), Fs);
        *dFout = dF;
        return;
    }
    double b = xi * dt;
    double a = kappa * dlam;
    F0 = pmin(pmax(F0, Fk), Fs);
    double recovery_max = form == SL_ONE_MINUS ? 1.0 : xpow(Fs / Fk - 1.0, n);
    if (b * recovery_max <= 1e-17 * Fk) {
        soften_exactly(F0, Fk, kappa, m, dlam, Fout, dFout);
        return;
    }
    if (a * xpow(Fs / Fk - 1.0, m) <= 1e-17 * Fk) {
        double F1 = recovered_size(F0, Fs, Fk, xi, m, n, dt, integrator, form);
        double phi, dphi;
        softening_rate(F1, Fk, m, &phi, &dphi);
        *Fout = F1;
        *dFout = -kappa * phi;
        return;
    }
    double F1, dF_da;
    constant_rate_size(F0, Fs, Fk, kappa * dlam, b, m, n, form, &F1, &dF_da);
    *Fout = F1;
    *dFout = kappa * dF_da;
}

/* ================================================================== kernels.py */
typedef struct {
    int surface;
    double tear_k;
    int ulaw, integ, rform;
    double A1, A2, Aref, alpha_t;
    double Fs, Fk, kappa, xi, m, n, u;
    double dt;
} law_t;

static inline double norm2(double x, double y)
{
    double s = x * x + y * y;
    if (1e-290 < s && s < 1e290) return sqrt(s);
    return hypot(x, y);
}

/* the point on the surface reached with the parameter q = gamma/(Aref^2 + gamma) from the
   trial traction (fh1t, fh2t): scaled traction t, plastic multiplier dlam and the
   potential phi(w, fn) with its derivatives (shared by state_at and model_at) */
typedef struct {
    double gamma, i1, i2, t1, t2, W, dlam, w, phi, phi_w, phi_fn;
} surface_point_t;

static void surface_point(double q, double omq, double fh1t, double fh2t, double fn,
                          const law_t *L, surface_point_t *p)
{
    double A1 = L->A1, A2 = L->A2, Aref = L->Aref;
    p->gamma = Aref * Aref * q / omq;
    p->i1 = 1.0 / (A1 * A1 + p->gamma);
    p->i2 = 1.0 / (A2 * A2 + p->gamma);
    p->t1 = fh1t * p->i1;
    p->t2 = fh2t * p->i2;
    p->W = norm2(p->t1, p->t2);
    p->dlam = p->gamma * p->W * (1.0 / L->alpha_t);
    p->w = norm2(A1 * p->t1, A2 * p->t2);
    potential(L->surface, L->tear_k, p->w, fn, &p->phi, &p->phi_w, &p->phi_fn);
}

/* the residual of the local solve and its derivatives (kernels._state_at) */
typedef struct {
    double r, r_gamma, phi_1, phi_2, dlam, R, dR, F, dF, phi_fn, gamma, W, hard, phi;
    double phi_gamma, rf_gamma, cond;
} state_t;

static void state_at(double q, double omq, double fh1t, double fh2t, double fn, const law_t *L,
                     double R0, double y0, double s0, double F0, state_t *o)
{
    double A1 = L->A1, A2 = L->A2, alpha_t = L->alpha_t;
    if (omq <= 0.0) {
        double dlam = norm2(fh1t, fh2t) / alpha_t;
        double R, dR, F, dF;
        ratio_from(L->ulaw, L->u, y0, s0, R0, dlam, &R, &dR);
        size_after(F0, L->Fs, L->Fk, L->kappa, L->xi, L->m, L->n, dlam, L->dt, L->integ,
                   L->rform, &F, &dF);
        double phi = L->surface == SL_COULOMB ? 0.0 : fn * 1.0;
        o->r = phi - R * F;
        o->r_gamma = 0.0;
        o->phi_1 = 0.0;
        o->phi_2 = 0.0;
        o->dlam = dlam;
        o->R = R;
        o->dR = dR;
        o->F = F;
        o->dF = dF;
        o->phi_fn = 0.0;
        o->gamma = 0.0;
        o->W = 0.0;
        o->hard = 0.0;
        o->phi = phi;
        o->phi_gamma = 0.0;
        o->rf_gamma = 0.0;
        o->cond = 0.0;
        return;
    }
    surface_point_t p;
    surface_point(q, omq, fh1t, fh2t, fn, L, &p);
    double gamma = p.gamma, i1 = p.i1, i2 = p.i2, t1 = p.t1, t2 = p.t2, W = p.W;
    double dlam = p.dlam, w = p.w, phi = p.phi, phi_w = p.phi_w, phi_fn = p.phi_fn;
    double R, dR, F, dF;
    ratio_from(L->ulaw, L->u, y0, s0, R0, dlam, &R, &dR);
    size_after(F0, L->Fs, L->Fk, L->kappa, L->xi, L->m, L->n, dlam, L->dt, L->integ, L->rform,
               &F, &dF);
    double r = phi - R * F;
    double dfh1 = -A1 * A1 * t1 * i1;
    double dfh2 = -A2 * A2 * t2 * i2;
    double phi_1, phi_2;
    if (w > 0.0) {
        double phi_per_w = phi_w / w;
        phi_1 = phi_per_w * t1;
        phi_2 = phi_per_w * t2;
    } else {
        phi_1 = 0.0;
        phi_2 = 0.0;
    }
    double dW = W > 0.0 ? -(t1 * t1 * i1 + t2 * t2 * i2) / W : 0.0;
    double ddlam = (W + gamma * dW) * (1.0 / alpha_t);
    double hard = dR * F + R * dF;
    double phi_gamma = phi_1 * dfh1 + phi_2 * dfh2;
    double rf_gamma = hard * ddlam;
    o->r = r;
    o->r_gamma = phi_gamma - rf_gamma;
    o->phi_1 = phi_1;
    o->phi_2 = phi_2;
    o->dlam = dlam;
    o->R = R;
    o->dR = dR;
    o->F = F;
    o->dF = dF;
    o->phi_fn = phi_fn;
    o->gamma = gamma;
    o->W = W;
    o->hard = hard;
    o->phi = phi;
    o->phi_gamma = phi_gamma;
    o->rf_gamma = rf_gamma;
    o->cond = phi_w * w;
}

static double path_size_slope(double F, double s, double Fs, double xi, double n, double dt,
                              int integ, int rform)
{
    double psi, dpsi;
    recovery_rate(F, Fs, n, rform, &psi, &dpsi);
    if (integ == SL_BACKWARD_EULER) {
        double den = 1.0 - xi * s * dt * dpsi;
        return (den > 0.0 && isfinite(den)) ? xi * dt * psi / den : 0.0;
    }
    return xi * dt * psi;
}

static void ratio_slope(double phi, double phi_w, double phi_fn, double w, double q1, double q2,
                        double e1, double e2, double dfn, double A1, double A2, double F,
                        double dF, double *rho, double *drho)
{
    if (!isfinite(phi)) {
        *rho = INFINITY;
        *drho = INFINITY;
        return;
    }
    double dw;
    if (w > 0.0)
        dw = ((q1 / A1) * (e1 / A1) + (q2 / A2) * (e2 / A2)) / w;
    else
        dw = norm2(e1 / A1, e2 / A2);
    double r = phi / F;
    *rho = r;
    *drho = (phi_w * dw + phi_fn * dfn) / F - r * dF / F;
}

/* the straight trial path: fhat(s) = h + s e, f_n(s) = fn0 + s dfn */
typedef struct {
    double h1, h2, e1, e2, fn0, dfn, F_old, dt; /* F_old and dt: the path's start and span */
} path_t;

typedef struct {
    double rho, drho, F, phi_w, phi_fn, w, q1, q2;
} path_pt;

static void path_ratio(double s, const path_t *P, const law_t *L, path_pt *o)
{
    double q1 = P->h1 + s * P->e1;
    double q2 = P->h2 + s * P->e2;
    double fns = P->fn0 + s * P->dfn;
    double w = norm2(q1 / L->A1, q2 / L->A2);
    double phi, phi_w, phi_fn;
    potential(L->surface, L->tear_k, w, fns, &phi, &phi_w, &phi_fn);
    double F = recovered_size(P->F_old, L->Fs, L->Fk, L->xi, L->m, L->n, s * P->dt, L->integ,
                              L->rform);
    double dF = path_size_slope(F, s, L->Fs, L->xi, L->n, P->dt, L->integ, L->rform);
    ratio_slope(phi, phi_w, phi_fn, w, q1, q2, P->e1, P->e2, P->dfn, L->A1, L->A2, F, dF,
                &o->rho, &o->drho);
    o->F = F;
    o->phi_w = phi_w;
    o->phi_fn = phi_fn;
    o->w = w;
    o->q1 = q1;
    o->q2 = q2;
}

static double path_minimum(const path_t *P, const law_t *L, double r0, double d0, double r1,
                           double d1)
{
    if (d0 >= 0.0 && d1 >= 0.0 && r1 >= r0) return 0.0;
    if (d0 <= 0.0 && d1 <= 0.0 && r1 <= r0) return 1.0;
    double best_s = 0.0;
    double best = r0;
    if (r1 < best) {
        best = r1;
        best_s = 1.0;
    }
    double s_a = 0.0;
    double d_a = d0;
    path_pt pt;
    for (int k = 1; k < PATH_SAMPLES + 1; k++) {
        double s_b = (double)k / (double)PATH_SAMPLES;
        double r_b, d_b;
        if (k == PATH_SAMPLES) {
            r_b = r1;
            d_b = d1;
        } else {
            path_ratio(s_b, P, L, &pt);
            r_b = pt.rho;
            d_b = pt.drho;
            if (r_b < best) {
                best = r_b;
                best_s = s_b;
            }
        }
        if (d_a < 0.0 && d_b > 0.0 && isfinite(d_b)) {
            double lo = s_a, hi = s_b;
            double f_lo = d_a, f_hi = d_b;
            int side = 0;
            double s_m = 0.5 * (lo + hi);
            for (int it = 0; it < 100; it++) {
                s_m = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
                if (!(lo < s_m && s_m < hi)) s_m = 0.5 * (lo + hi);
                path_ratio(s_m, P, L, &pt);
                double d_m = pt.drho;
                if (d_m == 0.0 || !isfinite(d_m)) break;
                if (d_m < 0.0) {
                    lo = s_m;
                    f_lo = d_m;
                    if (side == -1) f_hi *= 0.5;
                    side = -1;
                } else {
                    hi = s_m;
                    f_hi = d_m;
                    if (side == 1) f_lo *= 0.5;
                    side = 1;
                }
                if (hi - lo <= 1e-14) break;
            }
            path_ratio(s_m, P, L, &pt);
            double r_m = pt.rho;
            if (r_m < best) {
                best = r_m;
                best_s = s_m;
            }
        }
        s_a = s_b;
        d_a = d_b;
    }
    return best_s;
}

static void model_at(double q, double fh1t, double fh2t, double fn, const law_t *L, double R0,
                     double dR, double ddR, double dddR, double F0, double dF, double ddF,
                     double out[4])
{
    double A1 = L->A1, A2 = L->A2, Aref = L->Aref;
    double omq = 1.0 - q;
    surface_point_t p;
    surface_point(q, omq, fh1t, fh2t, fn, L, &p);
    double gamma = p.gamma, i1 = p.i1, i2 = p.i2, t1 = p.t1, t2 = p.t2, W = p.W;
    double dlam = p.dlam, w = p.w, phi = p.phi, phi_w = p.phi_w;
    double R = R0 + dlam * (dR + dlam * (0.5 * ddR + dlam * dddR * (1.0 / 6.0)));
    double Rp = dR + dlam * (ddR + 0.5 * dddR * dlam);
    if (R > 1.0 || Rp < 0.0) {
        R = pmin(R, 1.0);
        Rp = 0.0;
    }
    double F = F0 + dlam * (dF + 0.5 * ddF * dlam);
    dF = dF + ddF * dlam;
    double dphi = 0.0;
    if (w > 0.0) dphi = -phi_w * (A1 * A1 * t1 * t1 * i1 + A2 * A2 * t2 * t2 * i2) / w;
    double dW = W > 0.0 ? -(t1 * t1 * i1 + t2 * t2 * i2) / W : 0.0;
    double ddlam = (W + gamma * dW) * (1.0 / L->alpha_t);
    double dgamma = Aref * Aref / (omq * omq);
    out[0] = phi;
    out[1] = R * F;
    out[2] = dphi * dgamma;
    out[3] = (Rp * F + R * dF) * ddlam * dgamma;
}

static double domain_entry(double fh1t, double fh2t, double fn, const law_t *L)
{
    double edge;
    if (L->surface == SL_TEAR)
        edge = sqrt(2.0 * L->tear_k + 1.0) * fn;
    else if (L->surface == SL_PARABOLA)
        edge = 2.0 * fn;
    else
        return -1.0;
    double A1 = L->A1, A2 = L->A2, Aref = L->Aref;
    double target = (1.0 - 1e-3) * edge;
    double gamma = 0.0;
    for (int it = 0; it < 60; it++) {
        double i1 = 1.0 / (A1 * A1 + gamma);
        double i2 = 1.0 / (A2 * A2 + gamma);
        double v1 = A1 * fh1t * i1;
        double v2 = A2 * fh2t * i2;
        double w = norm2(v1, v2);
        if (w <= (1.0 - 5e-4) * edge) return gamma / (Aref * Aref + gamma);
        double dw = -(v1 * v1 * i1 + v2 * v2 * i2) / w;
        if (!(dw < 0.0 && isfinite(dw))) return -1.0;
        gamma -= (w - target) / dw;
    }
    return -1.0;
}

static double start_q(double r0, double r1, double phi_tr, double phi_tr_w, double w_tr,
                      double fh1t, double fh2t, double fn, const law_t *L, double R_start,
                      double y0, double s0, double F_rec)
{
    double u = L->u, kappa = L->kappa;
    double dR;
    if (L->ulaw == SL_U_COT)
        dR = s0 > 0.0 ? u * y0 / s0 : INFINITY;
    else
        dR = R_start > 0.0 ? -u * xlog(R_start) : INFINITY;
    double phi_soft, dphi_soft;
    softening_rate(F_rec, L->Fk, L->m, &phi_soft, &dphi_soft);
    double dF = -kappa * phi_soft;
    double q_floor = 0.0;
    int iterations = MODEL_ITERATIONS;
    double q;
    if (!isfinite(r0)) {
        q = domain_entry(fh1t, fh2t, fn, L);
        if (!(0.0 < q && q < 1.0 && isfinite(dR))) return -1.0;
        q_floor = q;
        iterations = DOMAIN_MODEL_ITERATIONS;
    } else {
        double A1 = L->A1, A2 = L->A2;
        double A2ref = L->Aref * L->Aref;
        double W0 = norm2(fh1t / (A1 * A1), fh2t / (A2 * A2));
        double dphi = phi_tr_w * W0 * W0 / w_tr * A2ref;
        double ddlam = W0 * A2ref / L->alpha_t;
        q = -1.0;
        double den = dphi + (dR * F_rec + R_start * dF) * ddlam;
        if (den > 0.0 && isfinite(den)) q = r0 / den;
        double r_sat = phi_tr - F_rec;
        double den_sat = dphi + dF * ddlam;
        if (r_sat > 0.0 && den_sat > 0.0 && isfinite(den_sat)) q = pmax(q, r_sat / den_sat);
    }
    if (0.0 < q && q < 1.0) {
        if (!isfinite(dR)) return q;
        double ddR, dddR;
        if (L->ulaw == SL_U_COT) {
            ddR = -0.5 * PI * (u * u + dR * dR) * dR / u;
            dddR = -0.5 * PI * ddR * (3.0 * dR * dR + u * u) / u;
        } else {
            ddR = -2.0 * u * dR / R_start;
            dddR = 3.0 * u * (dR * dR / R_start - ddR) / R_start;
        }
        double ddF = -kappa * dphi_soft * dF;
        int log_model = L->surface != SL_COULOMB && L->surface != SL_MODIFIED_CAM_CLAY;
        for (int it = 0; it < iterations; it++) {
            double mo[4];
            model_at(q, fh1t, fh2t, fn, L, R_start, dR, ddR, dddR, F_rec, dF, ddF, mo);
            double phi = mo[0], rf = mo[1], dphi_q = mo[2], drf_q = mo[3];
            double mq, dmq;
            if (log_model && phi > 0.0 && rf > 0.0) {
                mq = xlog(phi / rf);
                dmq = dphi_q / phi - drf_q / rf;
            } else {
                mq = phi - rf;
                dmq = dphi_q - drf_q;
            }
            if (!(dmq < 0.0 && isfinite(mq) && isfinite(dmq))) break;
            double q_new = q - mq / dmq;
            if (q_new <= q_floor)
                q_new = 0.5 * (q + q_floor);
            else if (q_new >= 1.0)
                q_new = 0.5 * (1.0 + q);
            int done = fabs(q_new - q) <= MODEL_RTOL * pmin(q_new, 1.0 - q_new);
            q = q_new;
            if (done) break;
        }
        return q;
    }
    if (isfinite(r1)) {
        q = r0 / (r0 - r1);
        if (0.0 < q && q < 1.0) return q;
    }
    q = phi_tr > 0.0 ? r0 / phi_tr : 0.5;
    return (0.0 < q && q < 1.0) ? q : 0.5;
}

/* ------------------------------------------------------------------ results */
static void result_set(sl_result *o, int status, int iterations, double t1, double t2, double tn,
                       double F, double R, double gap)
{
    o->status = status;
    o->iterations = iterations;
    o->traction[0] = t1;
    o->traction[1] = t2;
    o->traction[2] = tn;
    o->F = F;
    o->R = R;
    o->gap = gap;
    o->dlam = 0.0;
    o->vp[0] = 0.0;
    o->vp[1] = 0.0;
    o->diss = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) o->tangent[i][j] = 0.0;
}

static void set_k(sl_result *o, double k00, double k01, double k10, double k11, double k02,
                  double k12, double k22)
{
    o->tangent[0][0] = k00;
    o->tangent[0][1] = k01;
    o->tangent[1][0] = k10;
    o->tangent[1][1] = k11;
    o->tangent[0][2] = k02;
    o->tangent[1][2] = k12;
    o->tangent[2][2] = k22;
}

static int failed(sl_result *o, int iterations, double t1, double t2, double tn, double F_old,
                  double R_old, double gap_old, double alpha_t, double alpha_n, int want_tangent)
{
    result_set(o, SL_FAILED, iterations, t1, t2, tn, F_old, R_old, gap_old);
    if (want_tangent) set_k(o, alpha_t, 0.0, 0.0, alpha_t, 0.0, 0.0, alpha_n);
    return SL_FAILED;
}

static int slip_result(sl_result *o, int iterations, double dlam, double g1, double g2,
                       double tb1, double tb2, double fn, double F, double R, double ca,
                       double sa, double k00, double k01, double k10, double k11, double k02,
                       double k12, double k22)
{
    result_set(o, SL_SLIP, iterations, ca * g1 - sa * g2, sa * g1 + ca * g2, fn, F, R, 0.0);
    o->dlam = dlam;
    o->vp[0] = dlam * (ca * tb1 - sa * tb2);
    o->vp[1] = dlam * (sa * tb1 + ca * tb2);
    o->diss = dlam * (g1 * tb1 + g2 * tb2);
    set_k(o, k00, k01, k10, k11, k02, k12, k22);
    return SL_SLIP;
}

/* ------------------------------------------------------------------ the update */
static int point(double dt, double ca, double sa, const double *p, double t1_old,
                 double t2_old, double fn, double F_old, double R_old, double gap_old,
                 double slip1, double slip2, double dun, const sl_options *opt, sl_result *o)
{
    const int surface = opt->surface;
    const int want_tangent = opt->want_tangent;
    law_t L;
    double alpha_n = p[SL_P_ALPHA_N];
    double alpha_t = p[SL_P_ALPHA_T];
    L.surface = surface;
    L.tear_k = opt->tear_k;
    L.ulaw = opt->u_law;
    L.integ = opt->integrator;
    L.rform = opt->recovery;
    L.alpha_t = alpha_t;
    L.Fs = p[SL_P_FS];
    L.Fk = p[SL_P_FK];
    L.u = p[SL_P_U];
    L.kappa = p[SL_P_KAPPA];
    L.xi = p[SL_P_XI];
    L.m = p[SL_P_M];
    L.n = p[SL_P_N];
    L.A1 = p[SL_P_A1];
    L.A2 = p[SL_P_A2];
    L.Aref = pmax(L.A1, L.A2);
    L.dt = dt;
    const double Fs = L.Fs, Fk = L.Fk, xi = L.xi, m = L.m, n = L.n, A1 = L.A1, A2 = L.A2;
    const double Aref = L.Aref;
    const int integ = L.integ, rform = L.rform, ulaw = L.ulaw;
    const double tear_k = L.tear_k;
    /* 0. into principal axes */
    double b1 = ca * p[SL_P_BETA1] + sa * p[SL_P_BETA2];
    double b2 = -sa * p[SL_P_BETA1] + ca * p[SL_P_BETA2];
    double f1 = ca * t1_old + sa * t2_old;
    double f2 = -sa * t1_old + ca * t2_old;
    double du1 = ca * slip1 + sa * slip2;
    double du2 = -sa * slip1 + ca * slip2;

    /* 2. recovery-only size */
    double F_rec = recovered_size(F_old, Fs, Fk, xi, m, n, dt, integ, rform);
    /* 1. elastic predictor and separation */
    double closing_in = alpha_n * (dun - gap_old);
    double fn_tr = fn + closing_in;
    if (fn_tr <= SEPARATION_RTOL * pmax(fabs(fn), fabs(closing_in))) {
        result_set(o, SL_OPEN, 0, 0.0, 0.0, 0.0, opt->open_frozen ? F_old : F_rec, 0.0,
                   pmax(-fn_tr / alpha_n, 0.0));
        return SL_OPEN;
    }
    double et, f1t, f2t, h1, h2, fn0, hn1, hn2, en1, en2, f0n, dfnn, R_prev, F_path, dt_path;
    if (fn > 0.0) {
        et = alpha_t;
        f1t = f1 + alpha_t * du1;
        f2t = f2 + alpha_t * du2;
        h1 = f1 - fn * b1;
        h2 = f2 - fn * b2;
        fn0 = fn;
        hn1 = 0.0;
        hn2 = 0.0;
        en1 = -alpha_n * b1;
        en2 = -alpha_n * b2;
        f0n = 0.0;
        dfnn = alpha_n;
        R_prev = R_old;
        F_path = F_old;
        dt_path = dt;
    } else {
        /* re-closing: a virgin contact at the end-of-step normal traction */
        double s_c = dun > 0.0 ? gap_old / dun : 0.0;
        s_c = pmin(pmax(s_c, 0.0), 1.0);
        et = alpha_t * (1.0 - s_c);
        f1t = et * du1;
        f2t = et * du2;
        h1 = -fn_tr * b1;
        h2 = -fn_tr * b2;
        fn0 = fn_tr;
        hn1 = -alpha_n * b1;
        hn2 = -alpha_n * b2;
        double ds_c = (dun > 0.0 && 0.0 < s_c && s_c < 1.0) ? gap_old / (dun * dun) : 0.0;
        en1 = alpha_t * du1 * ds_c;
        en2 = alpha_t * du2 * ds_c;
        f0n = alpha_n;
        dfnn = 0.0;
        /* no memory: the virgin ratio starts the path, never above the surface (R <= 1);
         * the contact forms at the end of the step with the recovered size F_rec */
        R_prev = 1.0;
        F_path = F_rec;
        dt_path = 0.0;
    }
    double fh1t = f1t - fn_tr * b1;
    double fh2t = f2t - fn_tr * b2;
    path_t P;
    P.h1 = h1;
    P.h2 = h2;
    P.e1 = fh1t - h1;
    P.e2 = fh2t - h2;
    P.fn0 = fn0;
    P.dfn = fn_tr - fn0;
    P.F_old = F_path;
    P.dt = dt_path;
    double w_tr = norm2(fh1t / A1, fh2t / A2);
    double phi_tr, phi_tr_w, phi_tr_fn;
    potential(surface, tear_k, w_tr, fn_tr, &phi_tr, &phi_tr_w, &phi_tr_fn);

    /* 3. starting ratio: the smallest Phi/F along the trial path */
    double R_start = R_prev;
    int corrected = 0;
    double gR1 = 0.0, gR2 = 0.0, gRn = 0.0;
    double w0 = norm2(h1 / A1, h2 / A2);
    double phi0, phi0_w, phi0_fn;
    potential(surface, tear_k, w0, fn0, &phi0, &phi0_w, &phi0_fn);
    double dF0 = path_size_slope(F_path, 0.0, Fs, xi, n, dt_path, integ, rform);
    double r_0, d_0, r_1, d_1;
    ratio_slope(phi0, phi0_w, phi0_fn, w0, h1, h2, P.e1, P.e2, P.dfn, A1, A2, F_path, dF0, &r_0,
                &d_0);
    double dF1 = path_size_slope(F_rec, 1.0, Fs, xi, n, dt_path, integ, rform);
    ratio_slope(phi_tr, phi_tr_w, phi_tr_fn, w_tr, fh1t, fh2t, P.e1, P.e2, P.dfn, A1, A2, F_rec,
                dF1, &r_1, &d_1);
    double s_star = path_minimum(&P, &L, r_0, d_0, r_1, d_1);
    double rho;
    if (s_star == 0.0)
        rho = r_0;
    else if (s_star == 1.0)
        rho = r_1;
    else
        rho = INFINITY;
    double F_s = F_rec, phis_w = 0.0, phis_fn = 0.0, ws = 0.0, q1 = 0.0, q2 = 0.0;
    if (0.0 < s_star && s_star < 1.0) {
        path_pt pt;
        path_ratio(s_star, &P, &L, &pt);
        rho = pt.rho;
        F_s = pt.F;
        phis_w = pt.phi_w;
        phis_fn = pt.phi_fn;
        ws = pt.w;
        q1 = pt.q1;
        q2 = pt.q2;
    }
    /* a re-closing path starts at the virgin point of the end-of-step normal traction: its
     * ratio rho(0) depends on du_n, and so does R_start when the minimum is at s* = 0 */
    int reclosing_start = fn <= 0.0 && s_star == 0.0;
    if (reclosing_start) {
        F_s = F_path;
        phis_w = phi0_w;
        phis_fn = phi0_fn;
        ws = w0;
        q1 = h1;
        q2 = h2;
    }
    if (rho < R_start) {
        R_start = rho;
        if ((0.0 < s_star && s_star < 1.0) || reclosing_start) {
            corrected = 1;
            double u1, u2;
            if (ws > 0.0) {
                u1 = q1 / ws / (A1 * A1);
                u2 = q2 / ws / (A2 * A2);
            } else {
                u1 = 0.0;
                u2 = 0.0;
            }
            gR1 = phis_w * u1 * s_star * et / F_s;
            gR2 = phis_w * u2 * s_star * et / F_s;
            gRn = (phis_w * (u1 * (hn1 + s_star * en1) + u2 * (hn2 + s_star * en2)) +
                   phis_fn * (f0n + s_star * dfnn)) /
                  F_s;
        }
    }
    double ext1 = hn1 + en1 + alpha_n * b1;
    double ext2 = hn2 + en2 + alpha_n * b2;

    /* 4. loading test on the trial state */
    double r0 = phi_tr - R_start * F_rec;
    if (w_tr == 0.0 || r0 <= RTOL_RESIDUAL * F_rec) {
        double R_new = phi_tr / F_rec;
        if (surface != SL_COULOMB && R_new > 1.0 + RTOL_ACCEPT)
            return failed(o, 0, t1_old, t2_old, fn, F_old, R_old, gap_old, alpha_t, alpha_n,
                          want_tangent);
        if (R_new > 1.0) R_new = 1.0;
        result_set(o, SL_STICK, 0, ca * f1t - sa * f2t, sa * f1t + ca * f2t, fn_tr, F_rec, R_new,
                   0.0);
        if (want_tangent)
            set_k(o, et, 0.0, 0.0, et, ca * ext1 - sa * ext2, sa * ext1 + ca * ext2, alpha_n);
        return SL_STICK;
    }

    /* 5. plastic corrector on the bracket [0, 1] in q */
    double y0, s0;
    ratio_start(ulaw, R_start, &y0, &s0);
    int need_end;
    if (surface == SL_COULOMB)
        need_end = !(R_start > 0.0);
    else
        need_end = !(fn_tr < 0.999 * R_start * Fk);
    double r1 = -INFINITY;
    state_t res;
    if (need_end) {
        state_t end;
        state_at(1.0, 0.0, fh1t, fh2t, fn_tr, &L, R_start, y0, s0, F_old, &end);
        r1 = end.r;
        if (!(r1 < 0.0)) {
            double R_end = end.phi / end.F;
            if (surface == SL_COULOMB || R_end > 1.0 + RTOL_ACCEPT)
                return failed(o, 0, t1_old, t2_old, fn, F_old, R_old, gap_old, alpha_t, alpha_n,
                              want_tangent);
            double nrm = norm2(fh1t, fh2t);
            double k02 = want_tangent ? alpha_n * p[SL_P_BETA1] : 0.0;
            double k12 = want_tangent ? alpha_n * p[SL_P_BETA2] : 0.0;
            return slip_result(o, 0, end.dlam, fn_tr * b1, fn_tr * b2, fh1t / nrm, fh2t / nrm,
                               fn_tr, end.F, pmin(R_end, 1.0), ca, sa, 0.0, 0.0, 0.0, 0.0, k02,
                               k12, want_tangent ? alpha_n : 0.0);
        }
    }
    double q0 = start_q(r0, r1, phi_tr, phi_tr_w, w_tr, fh1t, fh2t, fn_tr, &L, R_start, y0, s0,
                        F_rec);
    if (q0 < 0.0) {
        state_at(0.5, 0.5, fh1t, fh2t, fn_tr, &L, R_start, y0, s0, F_old, &res);
        q0 = res.r > 0.0 ? 0.75 : 0.25;
    }
    int flip = q0 > 0.5;
    double dqdt = flip ? -1.0 : 1.0;
    double t = flip ? 1.0 - q0 : q0;
    double t_pos = flip ? 1.0 : 0.0;
    double t_neg = flip ? 0.0 : 1.0;
    int log_newton = surface != SL_COULOMB;
    int converged = 0;
    int it = 0;
    double dx = 1.0;
    double dx_old = 1.0;
    double q = flip ? 1.0 - t : t;
    double omq = flip ? t : 1.0 - t;
    state_at(q, omq, fh1t, fh2t, fn_tr, &L, R_start, y0, s0, F_old, &res);
    while (it < MAX_ITERATIONS) {
        it += 1;
        double r = res.r;
        double scale = pmax(res.F, 1e-300);
        if (fabs(r) <= RTOL_RESIDUAL * scale) {
            converged = 1;
            break;
        }
        if (r > 0.0)
            t_pos = t;
        else
            t_neg = t;
        double lo = pmin(t_pos, t_neg);
        double hi = pmax(t_pos, t_neg);
        if (hi - lo <= 4e-16 * pmax(hi, 1e-300)) {
            double cond = isfinite(res.cond) ? fabs(res.cond) : 0.0;
            converged = fabs(r) <= RTOL_ACCEPT * pmax(scale, cond);
            break;
        }
        double dgdt = Aref * Aref / (omq * omq) * dqdt;
        double t_new = -1.0;
        if (log_newton) {
            double phi = res.phi;
            double rf = res.R * res.F;
            if (phi > 0.0 && isfinite(phi) && rf > 0.0) {
                double dlog = (res.phi_gamma / phi - res.rf_gamma / rf) * dgdt;
                if (dlog != 0.0 && isfinite(dlog)) t_new = t - xlog(phi / rf) / dlog;
            }
        } else {
            double slope = res.r_gamma * dgdt;
            if (slope != 0.0 && isfinite(slope) && isfinite(r)) t_new = t - r / slope;
        }
        if (!(lo < t_new && t_new < hi) || fabs(t_new - t) > 0.5 * fabs(dx_old))
            t_new = 0.5 * (lo + hi);
        dx_old = dx;
        dx = t_new - t;
        t = t_new;
        if (t > 0.5) {
            flip = !flip;
            dqdt = -dqdt;
            t = 1.0 - t;
            t_pos = 1.0 - t_pos;
            t_neg = 1.0 - t_neg;
        }
        q = flip ? 1.0 - t : t;
        omq = flip ? t : 1.0 - t;
        state_at(q, omq, fh1t, fh2t, fn_tr, &L, R_start, y0, s0, F_old, &res);
    }
    if (!converged)
        return failed(o, it, t1_old, t2_old, fn, F_old, R_old, gap_old, alpha_t, alpha_n,
                      want_tangent);
    double r_gamma = res.r_gamma, phi_1 = res.phi_1, phi_2 = res.phi_2, dlam = res.dlam;
    double R = res.R, F = res.F, phi_fn = res.phi_fn, gamma = res.gamma, W = res.W;
    double hard = res.hard;
    double d1 = A1 * A1 + gamma;
    double d2 = A2 * A2 + gamma;
    double a1 = A1 * A1 / d1;
    double a2 = A2 * A2 / d2;
    double fh1 = fh1t * a1;
    double fh2 = fh2t * a2;
    /* 6. update (principal axes) */
    double tb1 = (fh1t / d1) / W;
    double tb2 = (fh2t / d2) / W;
    if (!want_tangent)
        return slip_result(o, it, dlam, fn_tr * b1 + fh1, fn_tr * b2 + fh2, tb1, tb2, fn_tr, F,
                           R, ca, sa, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    /* 7. consistent tangent */
    double ddl1 = gamma * (fh1t / (d1 * d1)) / (W * alpha_t);
    double ddl2 = gamma * (fh2t / (d2 * d2)) / (W * alpha_t);
    double c1 = (phi_1 * a1 - hard * ddl1) / r_gamma;
    double c2 = (phi_2 * a2 - hard * ddl2) / r_gamma;
    double cn = phi_fn / r_gamma;
    double G1 = -fh1 / d1;
    double G2 = -fh2 / d2;
    double j11 = a1 - G1 * c1;
    double j12 = -G1 * c2;
    double j21 = -G2 * c1;
    double j22 = a2 - G2 * c2;
    double jn1 = b1 - G1 * cn;
    double jn2 = b2 - G2 * cn;
    double T11 = et * j11;
    double T12 = et * j12;
    double T21 = et * j21;
    double T22 = et * j22;
    double T1n = alpha_n * (jn1 - j11 * b1 - j12 * b2) + j11 * ext1 + j12 * ext2;
    double T2n = alpha_n * (jn2 - j21 * b1 - j22 * b2) + j21 * ext1 + j22 * ext2;
    if (corrected) {
        double dR0 = ratio_sensitivity(ulaw, L.u, y0, s0, dlam, R);
        double cR = -F * dR0 / r_gamma;
        T11 -= G1 * cR * gR1;
        T12 -= G1 * cR * gR2;
        T21 -= G2 * cR * gR1;
        T22 -= G2 * cR * gR2;
        T1n -= G1 * cR * gRn;
        T2n -= G2 * cR * gRn;
    }
    double p11 = ca * T11 - sa * T21;
    double p12 = ca * T12 - sa * T22;
    double p21 = sa * T11 + ca * T21;
    double p22 = sa * T12 + ca * T22;
    return slip_result(o, it, dlam, fn_tr * b1 + fh1, fn_tr * b2 + fh2, tb1, tb2, fn_tr, F, R,
                       ca, sa, p11 * ca - p12 * sa, p11 * sa + p12 * ca, p21 * ca - p22 * sa,
                       p21 * sa + p22 * ca, ca * T1n - sa * T2n, sa * T1n + ca * T2n, alpha_n);
}

int sl_point(const double *p, double ca, double sa, const double *traction, double F_old,
             double R_old, double gap_old, const double *slip, double dt,
             const sl_options *opt, sl_result *out)
{
    /* the division-by-zero flag marks a division by zero inside this update; the
     * caller's flag is kept (cleared and raised again only in the rare case it was set) */
    int caller_flag = fetestexcept(FE_DIVBYZERO);
    if (caller_flag) feclearexcept(FE_DIVBYZERO);
    point(dt, ca, sa, p, traction[0], traction[1], traction[2], F_old, R_old, gap_old, slip[0],
          slip[1], slip[2], opt, out);
    int zero_division = fetestexcept(FE_DIVBYZERO) != 0;
    if (zero_division && !caller_flag) feclearexcept(FE_DIVBYZERO);
    if (caller_flag && !zero_division) feraiseexcept(FE_DIVBYZERO);
    int finite = isfinite(out->F) && isfinite(out->R) && isfinite(out->gap) &&
                 isfinite(out->dlam) && isfinite(out->diss);
    for (int i = 0; i < 3; i++) {
        finite = finite && isfinite(out->traction[i]);
        for (int j = 0; j < 3; j++) finite = finite && isfinite(out->tangent[i][j]);
    }
    if (zero_division || !finite)
        failed(out, 0, traction[0], traction[1], traction[2], F_old, R_old, gap_old,
               p[SL_P_ALPHA_T], p[SL_P_ALPHA_N], opt->want_tangent);
    return out->status;
}

void sl_step_points(long n, const double *traction, const double *F_old, const double *R_old,
                    const double *gap_old, const double *slip, const double *dt, long n_dt,
                    const double *P, long n_rows, const sl_options *opt, double *out_traction,
                    double *out_F, double *out_R, double *out_gap, double *out_dlam,
                    double *out_vp, double *out_diss, double *out_tangent, int *out_status,
                    int *out_iterations)
{
    double ca0 = 1.0, sa0 = 0.0;
    if (n_rows == 1) {
        ca0 = cos(P[SL_P_ANGLE]);
        sa0 = sin(P[SL_P_ANGLE]);
    }
    sl_result r;
    for (long i = 0; i < n; i++) {
        const double *p = P + (n_rows == 1 ? 0 : i) * SL_N_PARAMS;
        double ca = ca0, sa = sa0;
        if (n_rows != 1) {
            ca = cos(p[SL_P_ANGLE]);
            sa = sin(p[SL_P_ANGLE]);
        }
        sl_point(p, ca, sa, traction + 3 * i, F_old[i], R_old[i], gap_old[i], slip + 3 * i,
                 dt[n_dt == 1 ? 0 : i], opt, &r);
        out_status[i] = r.status;
        out_iterations[i] = r.iterations;
        for (int k = 0; k < 3; k++) out_traction[3 * i + k] = r.traction[k];
        out_F[i] = r.F;
        out_R[i] = r.R;
        out_gap[i] = r.gap;
        out_dlam[i] = r.dlam;
        out_vp[3 * i] = r.vp[0];
        out_vp[3 * i + 1] = r.vp[1];
        out_vp[3 * i + 2] = 0.0;
        out_diss[i] = r.diss;
        if (out_tangent && opt->want_tangent)
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++) out_tangent[9 * i + 3 * a + b] = r.tangent[a][b];
    }
}
