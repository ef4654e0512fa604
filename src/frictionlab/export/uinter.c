/*
 * uinter.c -- Abaqus user interactions calling the C core of the subloading-friction law:
 * UINTER (Abaqus/Standard) and VUINTER (Abaqus/Explicit). docs/fe-codes.md gives the
 * mapping and which conventions are verified against the Abaqus documentation.
 *
 * Local directions: Abaqus component 1 is the contact normal, 2 (and 3) the tangents. The
 * law's traction (f_t1, f_t2, f_n) is (STRESS(2), STRESS(3), STRESS(1)), compression
 * positive as in UINTER; its slip increment (du_t1, du_t2, du_n) is (DRDISP(2), DRDISP(3),
 * DRDISP(1)), DRDISP(1) the increment of the overclosure (the approach). With NDIR = 2
 * (two-dimensional models) the second tangential component is zero.
 *
 * PROPS (22): alpha_n, alpha_t, F_s (mu_s), F_k (mu_k), u, kappa, xi, m, n, beta_1,
 *   beta_2, A_1, A_2, orthotropy angle [rad], surface code, tear_k, U law code,
 *   integrator code, recovery form code, open recovery (0 continue, 1 frozen),
 *   initial F, initial R.
 * STATEV (8): F, R, opening [m], accumulated plastic slip [m], status of the last
 *   increment, local iterations, accumulated plastic work [J/m^2], initialised (1).
 *
 * A failed local solve keeps STRESS and STATEV, returns the elastic stiffness and asks
 * for a quarter of the time increment (PNEWDT = 0.25).
 */
#include <math.h>

#include "subloading.h"

#define FL_NPROPS 22
#define FL_NSTATV 8
#define FL_PNEWDT_FAILED 0.25

/* Fortran names: lower case with a trailing underscore (gfortran, ifort on Linux) unless
 * FL_FORTRAN_UPPER is defined (ifort on Windows) */
#ifdef FL_FORTRAN_UPPER
#define FL_UINTER UINTER
#define FL_VUINTER VUINTER
#else
#define FL_UINTER uinter_
#define FL_VUINTER vuinter_
#endif

/* law index of Abaqus local component k (0-based): normal first, then the tangents */
static const int LAW_OF[3] = {2, 0, 1};

static void law_from_props(const double *props, double p[SL_N_PARAMS], sl_options *opt)
{
    for (int k = 0; k < SL_N_PARAMS; k++) p[k] = props[k];
    opt->surface = (int)props[14];
    opt->tear_k = props[15];
    opt->u_law = (int)props[16];
    opt->integrator = (int)props[17];
    opt->recovery = (int)props[18];
    opt->open_frozen = props[19] != 0.0;
    opt->want_tangent = 1;
}

/*
 * One contact point: stress[ndir] and statev[8] at the start of the increment in, at its
 * end out; ddsddr[ndir*ndir] column major; drdisp, rdisp as UINTER. Returns the status.
 */
int frictionlab_interaction(int ndir, double *stress, double *ddsddr, double *statev,
                            const double *rdisp, const double *drdisp, double dt,
                            const double *props, double *pnewdt, double *work)
{
    double p[SL_N_PARAMS];
    sl_options opt;
    law_from_props(props, p, &opt);
    double traction[3] = {0.0, 0.0, 0.0};
    double slip[3] = {0.0, 0.0, 0.0};
    for (int k = 0; k < ndir; k++) {
        traction[LAW_OF[k]] = stress[k];
        slip[LAW_OF[k]] = drdisp[k];
    }
    if (statev[7] != 1.0) { /* first call: the scenario's initial state */
        statev[0] = props[20];
        statev[1] = props[21];
        /* opening at the start of the increment from the overclosure RDISP(1) at its end */
        double start = rdisp[0] - drdisp[0];
        statev[2] = traction[2] <= 0.0 && start < 0.0 ? -start : 0.0;
        statev[3] = 0.0;
        statev[6] = 0.0;
        statev[7] = 1.0;
    }
    sl_result r;
    int status = sl_point(p, cos(p[SL_P_ANGLE]), sin(p[SL_P_ANGLE]), traction, statev[0],
                          statev[1], statev[2], slip, dt, &opt, &r);
    for (int i = 0; i < ndir; i++)
        for (int j = 0; j < ndir; j++) ddsddr[i + j * ndir] = r.tangent[LAW_OF[i]][LAW_OF[j]];
    if (status == SL_FAILED) {
        if (*pnewdt > FL_PNEWDT_FAILED) *pnewdt = FL_PNEWDT_FAILED;
        return status; /* STRESS and STATEV kept; the elastic stiffness returned */
    }
    for (int k = 0; k < ndir; k++) stress[k] = r.traction[LAW_OF[k]];
    statev[0] = r.F;
    statev[1] = r.R;
    statev[2] = r.gap;
    statev[3] += r.dlam;
    statev[4] = (double)status;
    statev[5] = (double)r.iterations;
    statev[6] += r.diss;
    if (work) *work = r.diss;
    return status;
}

/* Abaqus/Standard: user subroutine UINTER (argument list of the Abaqus User Subroutines
 * Reference; CHARACTER*80 lengths, passed last by Fortran compilers, are not used) */
void FL_UINTER(double *stress, double *ddsddr, double *dviscous, double *dstructural,
               double *flux, double *ddfddt, double *ddsddt, double *ddfddr, double *statev,
               double *sed, double *sfd, double *spd, double *svd, double *scd, double *pnewdt,
               const double *rdisp, const double *drdisp, const double *temp,
               const double *dtemp, const double *predef, const double *dpred,
               const double *time, const double *dtime, const double *freqr,
               const char *ciname, const char *secname, const char *mainname,
               const double *props, const double *coords, const double *alocaldir,
               const double *drot, const double *area, const double *chrlngth, const int *node,
               const int *ndir, const int *nstatv, const int *npred, const int *nprops,
               const int *mcrd, const int *kstep, const int *kinc, const int *kit,
               const int *linper, int *lopenclose, int *lstate, int *lsdi, const int *lprint)
{
    (void)dviscous, (void)dstructural, (void)flux, (void)ddfddt, (void)ddsddt, (void)ddfddr;
    (void)sfd, (void)svd, (void)scd, (void)temp, (void)dtemp, (void)predef, (void)dpred;
    (void)time, (void)freqr, (void)ciname, (void)secname, (void)mainname, (void)coords;
    (void)alocaldir, (void)drot, (void)area, (void)chrlngth, (void)node, (void)npred;
    (void)mcrd, (void)kstep, (void)kinc, (void)kit, (void)lstate, (void)lprint;
    int n = *ndir;
    if (*nprops < FL_NPROPS || *nstatv < FL_NSTATV || n < 2 || n > 3) {
        *pnewdt = FL_PNEWDT_FAILED; /* wrong PROPERTIES/DEPVAR: no answer */
        return;
    }
    int was_closed = stress[0] > 0.0;
    double stress0[3] = {stress[0], stress[1], n > 2 ? stress[2] : 0.0};
    double statev0[FL_NSTATV];
    for (int k = 0; k < FL_NSTATV; k++) statev0[k] = statev[k];
    double work = 0.0;
    int status = frictionlab_interaction(n, stress, ddsddr, statev, rdisp, drdisp, *dtime,
                                         props, pnewdt, &work);
    if (*linper == 1) { /* linear perturbation: the tangent only, the base state kept */
        for (int k = 0; k < n; k++) stress[k] = stress0[k];
        for (int k = 0; k < FL_NSTATV; k++) statev[k] = statev0[k];
        return;
    }
    if (status == SL_FAILED) return;
    int closed = status != SL_OPEN;
    *lopenclose = closed;
    if (closed != was_closed) *lsdi = 1; /* the contact opened or closed: iterate again */
    /* elastic energy density f_t^2/(2 alpha_t) + f_n^2/(2 alpha_n); plastic dissipation */
    double e = 0.0;
    for (int k = 0; k < n; k++) e += stress[k] * stress[k] / (k == 0 ? props[0] : props[1]);
    *sed = 0.5 * e;
    *spd += work;
}

/* Abaqus/Explicit: user subroutine VUINTER (nSlvNod points in one call; arrays with the
 * component first: stress(nDir, nSlvNod), statev(nStateVar, nSlvNod)). */
void FL_VUINTER(double *sfd, double *scd, double *spd, double *svd, double *stress,
                double *fluxSlv, double *fluxMst, double *sed, double *statev,
                const int *kStep, const int *kInc, const int *nFacNod, const int *nSlvNod,
                const int *nMstNod, const int *nSurfDir, const int *nDir,
                const int *nStateVar, const int *nProps, const int *nTemp, const int *nPred,
                const int *numDefTfv, const int *jSlvUid, const int *jMstUid,
                const int *jConMstid, const double *timStep, const double *timGlb,
                const double *dTimPrev, const double *surfInt, const double *surfSlv,
                const double *surfMst, const int *lContType, int *lOpenClose,
                const int *lAvgArea, const int *lAnyChange, const int *lShape,
                const double *rdisp, const double *drdisp, const double *drot,
                const double *stiffDflt, const double *condDflt, const double *shape,
                const double *coordSlv, const double *coordMst, const double *alocaldir,
                const double *props, const double *areaSlv, const double *tempSlv,
                const double *dtempSlv, const double *preDefSlv, const double *dpreDefSlv,
                const double *tempMst, const double *dtempMst, const double *preDefMst,
                const double *dpreDefMst)
{
    (void)sfd, (void)scd, (void)svd, (void)fluxSlv, (void)fluxMst, (void)kStep, (void)kInc;
    (void)nFacNod, (void)nMstNod, (void)nSurfDir, (void)nTemp, (void)nPred, (void)numDefTfv;
    (void)jSlvUid, (void)jMstUid, (void)jConMstid, (void)timStep, (void)timGlb, (void)surfInt;
    (void)surfSlv, (void)surfMst, (void)lContType, (void)lAvgArea, (void)lAnyChange;
    (void)lShape, (void)drot, (void)stiffDflt, (void)condDflt, (void)shape, (void)coordSlv;
    (void)coordMst, (void)alocaldir, (void)areaSlv, (void)tempSlv, (void)dtempSlv;
    (void)preDefSlv, (void)dpreDefSlv, (void)tempMst, (void)dtempMst, (void)preDefMst;
    (void)dpreDefMst;
    int n = *nDir, ns = *nStateVar;
    if (*nProps < FL_NPROPS || ns < FL_NSTATV || n < 2 || n > 3) return;
    for (int k = 0; k < *nSlvNod; k++) {
        double ddsddr[9], pnewdt = 1.0, work = 0.0;
        double *s = stress + (long)k * n;
        int status = frictionlab_interaction(n, s, ddsddr, statev + (long)k * ns,
                                             rdisp + (long)k * n, drdisp + (long)k * n,
                                             *dTimPrev, props, &pnewdt, &work);
        lOpenClose[k] = status != SL_OPEN;
        double e = 0.0;
        for (int i = 0; i < n; i++) e += s[i] * s[i] / (i == 0 ? props[0] : props[1]);
        sed[k] = 0.5 * e;
        spd[k] += work;
    }
}
