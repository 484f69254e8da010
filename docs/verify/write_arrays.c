/* Dump a DEM code's screening arrays for `nbscope verify` (Munjiza, ch. 3, screening: the screen
 * array C[nx][ny] of list heads and the next array E[N]). Copy write_screen_arrays() into your
 * code and call it right after the lists are built, before the contact loop uses them.
 *
 * The JSON is the schema `nbscope dump --algorithm screen` writes, 0-based: element k is row k of
 * the elements CSV, cell (ix, iy) spans [x0 + ix*d, x0 + (ix+1)*d) x [y0 + iy*d, y0 + (iy+1)*d),
 * and -1 is an empty list or the end of one.
 *
 *   cc -std=c99 -Wall -Wextra -pedantic write_arrays.c -o write_arrays && ./write_arrays > arrays.json
 *   nbscope verify --input nine.csv --arrays arrays.json --algorithm screen \
 *                  --cell-size 1 --origin 0,0 --cells 10,10
 *
 * Add -DPLANT_BUG to build the arrays of a code with one bug in it, for verify to find.
 */
#include <stdio.h>

static void write_ints(FILE *out, const int *a, int n)
{
    for (int i = 0; i < n; ++i)
        fprintf(out, "%s%d", i ? ", " : "", a[i]);
}

/* heads: C[ix][iy] at heads[ix*ny + iy], the layout of a C array int C[nx][ny]; next: E[0..n-1].
 * Returns 0, or -1 if writing failed. %.17g prints each double so it reads back bit for bit
 * (it assumes the "C" locale's decimal point, the default unless your code calls setlocale). */
int write_screen_arrays(FILE *out, int n, int nx, int ny, double d, double x0, double y0,
                        const int *heads, const int *next)
{
    fprintf(out, "{\n  \"algorithm\": \"screen\",\n  \"dim\": 2,\n  \"elements\": %d,\n", n);
    fprintf(out, "  \"cell_size\": %.17g,\n  \"origin\": [%.17g, %.17g],\n", d, x0, y0);
    fprintf(out, "  \"nx\": %d,\n  \"ny\": %d,\n  \"heads\": [\n", nx, ny);
    for (int ix = 0; ix < nx; ++ix) {
        fputs("    [", out);
        write_ints(out, heads + (long)ix * ny, ny);
        fputs(ix + 1 < nx ? "],\n" : "]\n", out);
    }
    fputs("  ],\n  \"next\": [", out);
    write_ints(out, next, n);
    fputs("]\n}\n", out);
    return ferror(out) ? -1 : 0;
}

/* ---- the example: the nine elements of the book's Fig. 3.15 (assets/examples/nine.csv) ---- */

#define N 9
#define NX 10
#define NY 10

int main(void)
{
    static const double x[N] = {4.75, 4.90, 1.85, 4.60, 1.30, 4.50, 1.60, 5.20, 1.20};
    static const double y[N] = {6.45, 6.50, 6.45, 6.80, 6.85, 5.55, 6.60, 5.40, 6.55};
    const double d = 1.0, x0 = 0.0, y0 = 0.0;
    int C[NX * NY], E[N]; /* C[ix][iy] is C[ix * NY + iy] */

    for (int c = 0; c < NX * NY; ++c)
        C[c] = -1;
    for (int k = 0; k < N; ++k) {
        /* (int) truncates toward zero: the cell's index only for centres at or past the origin,
           as all nine are (use floor() if yours may lie below it). */
        int ix = (int)((x[k] - x0) / d), iy = (int)((y[k] - y0) / d);
#ifdef PLANT_BUG
        if (k == 3)
            iy -= 1; /* element 3 (the book's 4) lands one row low: on C[4][5]'s list, not C[4][6]'s */
#endif
        E[k] = C[ix * NY + iy]; /* push k at the head of its cell's list */
        C[ix * NY + iy] = k;
    }
    return write_screen_arrays(stdout, N, NX, NY, d, x0, y0, C, E) == 0 ? 0 : 1;
}
