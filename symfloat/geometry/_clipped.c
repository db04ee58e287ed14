/* The float64 draught's inner step in C: the volume below the plane u . p = t and the waterplane's area,
 * ``symfloat.geometry.floating._volume_and_area`` with the same operations in the same order, so that
 * both give the same doubles bit for bit (tests/test_clipped_kernel.py compares them).  Built by setup.py
 * with -ffp-contract=off (no fused multiply-add); where it is not built the Python function serves.
 *
 * The body comes packed once (``floating._packed``): its face rings' vertices as doubles (x, y, z per
 * vertex, ring after ring) and the rings' lengths as 32-bit integers. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#define MAX_RING 512        /* a clipped ring has at most one point more than its face */

static PyObject *
volume_and_area(PyObject *self, PyObject *args)
{
    Py_buffer points, sizes;
    double u0, u1, u2, t;
    if (!PyArg_ParseTuple(args, "y*y*dddd", &points, &sizes, &u0, &u1, &u2, &t))
        return NULL;
    const double *p = (const double *)points.buf;
    const int *n_of = (const int *)sizes.buf;
    Py_ssize_t rings = sizes.len / (Py_ssize_t)sizeof(int);
    double heights[MAX_RING], out[3 * (MAX_RING + 1)];
    double o0 = t * u0, o1 = t * u1, o2 = t * u2;
    double volume = 0.0, n0 = 0.0, n1 = 0.0, n2 = 0.0;
    Py_ssize_t start = 0;
    for (Py_ssize_t f = 0; f < rings; f++) {
        int n = n_of[f];
        const double *ring = p + 3 * start;
        start += n;
        if (n > MAX_RING || 3 * start * (Py_ssize_t)sizeof(double) > points.len) {
            PyBuffer_Release(&points);
            PyBuffer_Release(&sizes);
            PyErr_SetString(PyExc_ValueError, "a face ring longer than the kernel takes, or the rings overrun the points");
            return NULL;
        }
        int on_plane = 1;
        for (int i = 0; i < n; i++) {
            heights[i] = u0 * ring[3 * i] + u1 * ring[3 * i + 1] + u2 * ring[3 * i + 2];
            on_plane = on_plane && heights[i] == t;
        }
        if (on_plane) {         /* a top face in the plane (Newell's normal along +u) is replaced by the cap */
            double c0 = 0.0, c1 = 0.0, c2 = 0.0;
            for (int i = 0; i < n; i++) {
                const double *a = ring + 3 * i, *b = ring + 3 * ((i + 1) % n);
                c0 = c0 + (a[1] * b[2] - a[2] * b[1]);
                c1 = c1 + (a[2] * b[0] - a[0] * b[2]);
                c2 = c2 + (a[0] * b[1] - a[1] * b[0]);
            }
            if (c0 * u0 + c1 * u1 + c2 * u2 > 0)
                continue;
        }
        int m = 0;              /* the clipped ring (Sutherland-Hodgman against u . p <= t) */
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            const double *q = ring + 3 * i, *r = ring + 3 * j;
            double hp = heights[i], hq = heights[j];
            if (hp <= t) {
                out[3 * m] = q[0]; out[3 * m + 1] = q[1]; out[3 * m + 2] = q[2];
                m++;
            }
            if ((hp <= t) != (hq <= t)) {   /* from the point below to the point above, as in Python */
                const double *a = hp <= t ? q : r, *b = hp <= t ? r : q;
                double ha = hp <= t ? hp : hq, hb = hp <= t ? hq : hp;
                double s = (t - ha) / (hb - ha);
                out[3 * m] = a[0] + s * (b[0] - a[0]);
                out[3 * m + 1] = a[1] + s * (b[1] - a[1]);
                out[3 * m + 2] = a[2] + s * (b[2] - a[2]);
                m++;
            }
        }
        if (m < 3)
            continue;
        double x0 = out[3 * (m - 1)] - o0, y0 = out[3 * (m - 1) + 1] - o1, z0 = out[3 * (m - 1) + 2] - o2;
        double f0 = 0.0, f1 = 0.0, f2 = 0.0;
        for (int i = 0; i < m; i++) {
            double x1 = out[3 * i] - o0, y1 = out[3 * i + 1] - o1, z1 = out[3 * i + 2] - o2;
            f0 += y0 * z1 - z0 * y1;
            f1 += z0 * x1 - x0 * z1;
            f2 += x0 * y1 - y0 * x1;
            x0 = x1; y0 = y1; z0 = z1;
        }
        volume += x0 * f0 + y0 * f1 + z0 * f2;
        n0 = n0 + f0; n1 = n1 + f1; n2 = n2 + f2;
    }
    PyBuffer_Release(&points);
    PyBuffer_Release(&sizes);
    return Py_BuildValue("dd", volume / 6, -(u0 * n0 + u1 * n1 + u2 * n2) / 2);
}

static PyMethodDef methods[] = {
    {"volume_and_area", volume_and_area, METH_VARARGS,
     "volume_and_area(points, sizes, u0, u1, u2, t) -> (V, A): the volume below u . p = t and the waterplane's "
     "area of a packed float64 body (see symfloat.geometry.floating._volume_and_area)."},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_clipped", NULL, -1, methods};

PyMODINIT_FUNC
PyInit__clipped(void)
{
    return PyModule_Create(&module);
}
