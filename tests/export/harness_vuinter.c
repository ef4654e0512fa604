/* Plays Abaqus/Explicit's part for VUINTER: all records of the input (harness_uinter.f90
 * layout, one shared PROPS) in one call of nSlvNod nodes, arrays component first.
 * Output per node: stress(3), statev(8), lOpenClose, sed, spd. */
#include <stdio.h>
#include <stdlib.h>

void vuinter_(double *sfd, double *scd, double *spd, double *svd, double *stress,
              double *fluxSlv, double *fluxMst, double *sed, double *statev, const int *kStep,
              const int *kInc, const int *nFacNod, const int *nSlvNod, const int *nMstNod,
              const int *nSurfDir, const int *nDir, const int *nStateVar, const int *nProps,
              const int *nTemp, const int *nPred, const int *numDefTfv, const int *jSlvUid,
              const int *jMstUid, const int *jConMstid, const double *timStep,
              const double *timGlb, const double *dTimPrev, const double *surfInt,
              const double *surfSlv, const double *surfMst, const int *lContType,
              int *lOpenClose, const int *lAvgArea, const int *lAnyChange, const int *lShape,
              const double *rdisp, const double *drdisp, const double *drot,
              const double *stiffDflt, const double *condDflt, const double *shape,
              const double *coordSlv, const double *coordMst, const double *alocaldir,
              const double *props, const double *areaSlv, const double *tempSlv,
              const double *dtempSlv, const double *preDefSlv, const double *dpreDefSlv,
              const double *tempMst, const double *dtempMst, const double *preDefMst,
              const double *dpreDefMst);

int main(int argc, char **argv)
{
    if (argc != 3) return 2;
    FILE *in = fopen(argv[1], "rb");
    double header;
    if (!in || fread(&header, sizeof header, 1, in) != 1) return 1;
    int n = (int)header, ndir = 3, ns = 8, np = 22, zero = 0, one = 1;
    double *rec = malloc(sizeof(double) * 41 * n);
    if (fread(rec, sizeof(double), 41 * (size_t)n, in) != 41 * (size_t)n) return 1;
    fclose(in);
    double *stress = calloc(3 * n, sizeof(double)), *statev = calloc(8 * n, sizeof(double));
    double *rdisp = calloc(3 * n, sizeof(double)), *drdisp = calloc(3 * n, sizeof(double));
    double *sed = calloc(n, sizeof(double)), *spd = calloc(n, sizeof(double));
    double *dummy = calloc(9 * n + 64, sizeof(double));
    int *lopen = calloc(n, sizeof(int)), *idummy = calloc(n + 8, sizeof(int));
    for (int k = 0; k < n; k++) {
        for (int i = 0; i < 3; i++) {
            stress[3 * k + i] = rec[41 * k + 23 + i];
            rdisp[3 * k + i] = rec[41 * k + 34 + i];
            drdisp[3 * k + i] = rec[41 * k + 37 + i];
        }
        for (int i = 0; i < 8; i++) statev[8 * k + i] = rec[41 * k + 26 + i];
    }
    double dt = rec[40];
    vuinter_(dummy, dummy, spd, dummy, stress, dummy, dummy, sed, statev, &one, &one, &one, &n,
             &one, &ndir, &ndir, &ns, &np, &zero, &zero, &zero, idummy, idummy, idummy, dummy,
             dummy, &dt, dummy, dummy, dummy, idummy, lopen, idummy, idummy, idummy, rdisp,
             drdisp, dummy, dummy, dummy, dummy, dummy, dummy, dummy, rec + 1, dummy, dummy,
             dummy, dummy, dummy, dummy, dummy, dummy, dummy);
    FILE *out = fopen(argv[2], "wb");
    for (int k = 0; k < n; k++) {
        double row[14];
        for (int i = 0; i < 3; i++) row[i] = stress[3 * k + i];
        for (int i = 0; i < 8; i++) row[3 + i] = statev[8 * k + i];
        row[11] = lopen[k];
        row[12] = sed[k];
        row[13] = spd[k];
        fwrite(row, sizeof(double), 14, out);
    }
    fclose(out);
    return 0;
}
