/* The float64 body clipped by the water plane, in C: the draught's step (the volume below the plane
 * u . p = t and the waterplane's area, ``symfloat.geometry.floating._volume_and_area``) and the submerged
 * part (its volume and centroid, the waterplane polygon and its moments, ``floating._submerged_part``),
 * with the same operations in the same order as the Python functions, so that both give the same doubles bit
 * for bit (tests/test_clipped_step.py compares them).  Built by setup.py with -ffp-contract=off (no fused
 * multiply-add); where it is not built the Python functions serve.
 *
 * The body comes packed once (``Polyhedron.packed``): its face rings' vertices as doubles (x, y, z per
 * vertex, ring after ring) and the rings' lengths as 32-bit integers. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <stdlib.h>

#define MAX_RING 512        /* the longest face ring taken; a clipped ring has at most twice its points */

/* floating._clip for one face ring of n points: the clipped ring (Sutherland-Hodgman against u . p <= t) into
 * out, its length returned, or -1 for a top face lying in the plane (Newell's normal along +u), which the cap
 * replaces; where plane is not NULL, the points lying on the plane are appended to it (*on counts them) */
static int
clip_ring(const double *ring, int n, double u0, double u1, double u2, double t, double *out, double *plane,
          Py_ssize_t *on)
{
    double heights[MAX_RING];
    int in_plane = 1;
    for (int i = 0; i < n; i++) {
        heights[i] = u0 * ring[3 * i] + u1 * ring[3 * i + 1] + u2 * ring[3 * i + 2];
        in_plane = in_plane && heights[i] == t;
    }
    if (in_plane) {
        double c0 = 0.0, c1 = 0.0, c2 = 0.0;
        for (int i = 0; i < n; i++) {
            const double *a = ring + 3 * i, *b = ring + 3 * ((i + 1) % n);
            c0 = c0 + (a[1] * b[2] - a[2] * b[1]);
            c1 = c1 + (a[2] * b[0] - a[0] * b[2]);
            c2 = c2 + (a[0] * b[1] - a[1] * b[0]);
        }
        if (c0 * u0 + c1 * u1 + c2 * u2 > 0) {
            for (int i = 0; plane != NULL && i < n; i++, (*on)++)
                for (int k = 0; k < 3; k++) plane[3 * *on + k] = ring[3 * i + k];
            return -1;
        }
    }
    int m = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        const double *q = ring + 3 * i, *r = ring + 3 * j;
        double hp = heights[i], hq = heights[j];
        if (hp <= t) {
            for (int k = 0; k < 3; k++) out[3 * m + k] = q[k];
            if (plane != NULL && hp == t) {
                for (int k = 0; k < 3; k++) plane[3 * *on + k] = q[k];
                (*on)++;
            }
            m++;
        }
        if ((hp <= t) != (hq <= t)) {   /* from the point below to the point above, as in Python */
            const double *a = hp <= t ? q : r, *b = hp <= t ? r : q;
            double ha = hp <= t ? hp : hq, hb = hp <= t ? hq : hp;
            double s = (t - ha) / (hb - ha);
            out[3 * m] = a[0] + s * (b[0] - a[0]);
            out[3 * m + 1] = a[1] + s * (b[1] - a[1]);
            out[3 * m + 2] = a[2] + s * (b[2] - a[2]);
            if (plane != NULL) {
                for (int k = 0; k < 3; k++) plane[3 * *on + k] = out[3 * m + k];
                (*on)++;
            }
            m++;
        }
    }
    return m;
}

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
    double out[3 * 2 * MAX_RING];
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
        int m = clip_ring(ring, n, u0, u1, u2, t, out, NULL, NULL);
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

/* -- the submerged part ------------------------------------------------------------------------------ */

typedef struct { double x, y; Py_ssize_t point; } Key;     /* a waterplane point's plane coordinates */

static int
key_order(const void *a, const void *b)     /* tuples' order: by x, then by y (the keys are distinct) */
{
    const Key *p = a, *q = b;
    if (p->x < q->x) return -1;
    if (p->x > q->x) return 1;
    if (p->y < q->y) return -1;
    if (p->y > q->y) return 1;
    return 0;
}

static double
cross2(const Key *o, const Key *a, const Key *b)    /* convex._cross2 */
{
    return (a->x - o->x) * (b->y - o->y) - (a->y - o->y) * (b->x - o->x);
}

/* convex.hull_2d of the n distinct keys (sorted here): the hull's keys, counter-clockwise, into hull;
 * returns their number */
static Py_ssize_t
hull_2d(Key *keys, Py_ssize_t n, Key *hull, Key *chain)
{
    qsort(keys, (size_t)n, sizeof(Key), key_order);
    if (n <= 2) {
        for (Py_ssize_t i = 0; i < n; i++) hull[i] = keys[i];
        return n;
    }
    Py_ssize_t m = 0, h = 0;
    for (Py_ssize_t i = 0; i < n; i++) {        /* the lower chain */
        while (m >= 2 && cross2(&chain[m - 2], &chain[m - 1], &keys[i]) <= 0) m--;
        chain[m++] = keys[i];
    }
    for (Py_ssize_t i = 0; i < m - 1; i++) hull[h++] = chain[i];
    m = 0;
    for (Py_ssize_t i = n - 1; i >= 0; i--) {   /* the upper chain */
        while (m >= 2 && cross2(&chain[m - 2], &chain[m - 1], &keys[i]) <= 0) m--;
        chain[m++] = keys[i];
    }
    for (Py_ssize_t i = 0; i < m - 1; i++) hull[h++] = chain[i];
    return h;
}

static PyObject *
pair(double a, double b) { return Py_BuildValue("(dd)", a, b); }

static PyObject *
triple(const double *p) { return Py_BuildValue("(ddd)", p[0], p[1], p[2]); }

/* submerged(points, sizes, u0, u1, u2, t, e1 (3 doubles), e2 (3 doubles)) -> (volume, centroid | None,
 * polygon, area, plane centroid | None, tensor | None): floating._submerged_part with u a unit vector and
 * (e1, e2) its waterplane basis */
static PyObject *
submerged(PyObject *self, PyObject *args)
{
    Py_buffer points, sizes;
    double u0, u1, u2, t, f0, f1, f2, g0, g1, g2;
    if (!PyArg_ParseTuple(args, "y*y*dddd(ddd)(ddd)", &points, &sizes, &u0, &u1, &u2, &t, &f0, &f1, &f2,
                          &g0, &g1, &g2))
        return NULL;
    const double *p = (const double *)points.buf;
    const int *n_of = (const int *)sizes.buf;
    Py_ssize_t rings = sizes.len / (Py_ssize_t)sizeof(int), total = 0;
    for (Py_ssize_t f = 0; f < rings; f++) {
        if (n_of[f] < 0 || n_of[f] > MAX_RING) total = -1;
        if (total < 0) break;
        total += n_of[f];
    }
    PyObject *result = NULL;
    double *faces = NULL, *plane = NULL, *verts = NULL;
    int *face_n = NULL;
    Key *keys = NULL, *hull = NULL, *chain = NULL;
    if (total < 0 || 3 * total * (Py_ssize_t)sizeof(double) > points.len) {
        PyErr_SetString(PyExc_ValueError, "a face ring longer than the kernel takes, or the rings overrun the points");
        goto done;
    }
    /* a ring keeps at most its points and adds at most one crossing per edge; the points on the plane are at
     * most those, and the cap at most them */
    Py_ssize_t room = 4 * total + 8;
    faces = malloc(sizeof(double) * 3 * (size_t)room);
    plane = malloc(sizeof(double) * 3 * (size_t)room);
    verts = malloc(sizeof(double) * 3 * (size_t)room);
    face_n = malloc(sizeof(int) * (size_t)(rings + 1));
    keys = malloc(sizeof(Key) * (size_t)room);
    hull = malloc(sizeof(Key) * (size_t)room);
    chain = malloc(sizeof(Key) * (size_t)room);
    if (!faces || !plane || !verts || !face_n || !keys || !hull || !chain) {
        PyErr_NoMemory();
        goto done;
    }
    /* floating._clip: every ring clipped; the points on the plane, in order */
    Py_ssize_t start = 0, used = 0, on = 0, kept = 0;
    for (Py_ssize_t f = 0; f < rings; f++) {
        int m = clip_ring(p + 3 * start, n_of[f], u0, u1, u2, t, faces + 3 * used, plane, &on);
        start += n_of[f];
        if (m >= 3) {
            face_n[kept++] = m;
            used += m;
        }
    }
    /* floating._cap: the plane coordinates of the points on the plane, the first point of each kept */
    double o0 = t * u0, o1 = t * u1, o2 = t * u2;
    Py_ssize_t distinct = 0;
    for (Py_ssize_t i = 0; i < on; i++) {
        double d0 = plane[3 * i] - o0, d1 = plane[3 * i + 1] - o1, d2 = plane[3 * i + 2] - o2;
        double x = d0 * f0 + d1 * f1 + d2 * f2, y = d0 * g0 + d1 * g1 + d2 * g2;
        Py_ssize_t j = 0;
        while (j < distinct && !(keys[j].x == x && keys[j].y == y)) j++;
        if (j == distinct) {
            keys[distinct].x = x;
            keys[distinct].y = y;
            keys[distinct++].point = i;
        }
    }
    Py_ssize_t h = hull_2d(keys, distinct, hull, chain);
    /* floating._polygon_moments of the hull */
    double area = 0.0, cx = 0.0, cy = 0.0, mx = 0.0, my = 0.0, J[3] = {0.0, 0.0, 0.0};
    int moments = 0;
    if (h >= 3) {
        for (Py_ssize_t i = 0; i < h; i++) mx += hull[i].x;
        for (Py_ssize_t i = 0; i < h; i++) my += hull[i].y;
        mx = mx / (double)h;
        my = my / (double)h;
        double A = 0.0, Sx = 0.0, Sy = 0.0, Sxx = 0.0, Sxy = 0.0, Syy = 0.0;
        for (Py_ssize_t i = 0; i < h; i++) {
            const Key *a = &hull[i], *b = &hull[(i + 1) % h];
            double xi = a->x - mx, yi = a->y - my, xj = b->x - mx, yj = b->y - my;
            double c = xi * yj - xj * yi;
            A += c;
            Sx += (xi + xj) * c;
            Sy += (yi + yj) * c;
            Sxx += (xi * xi + xi * xj + xj * xj) * c;
            Syy += (yi * yi + yi * yj + yj * yj) * c;
            Sxy += (2 * xi * yi + xi * yj + xj * yi + 2 * xj * yj) * c;
        }
        A /= 2;
        area = A;
        if (A != 0) {
            moments = 1;
            cx = Sx / 6 / A;
            cy = Sy / 6 / A;
            J[0] = Sxx / 12 - A * cx * cx;
            J[1] = Sxy / 24 - A * cx * cy;
            J[2] = Syy / 12 - A * cy * cy;
        }
    }
    /* the cap closes the clipped faces */
    if (h >= 3) {
        for (Py_ssize_t i = 0; i < h; i++)
            for (int k = 0; k < 3; k++) faces[3 * (used + i) + k] = plane[3 * hull[i].point + k];
        face_n[kept++] = (int)h;
        used += h;
    }
    /* floating.volume_centroid of the submerged part: its distinct vertices (the first of each) and their mean */
    Py_ssize_t nv = 0;
    for (Py_ssize_t i = 0; i < used; i++) {
        const double *v = faces + 3 * i;
        Py_ssize_t j = 0;
        while (j < nv && !(verts[3 * j] == v[0] && verts[3 * j + 1] == v[1] && verts[3 * j + 2] == v[2])) j++;
        if (j == nv) {
            for (int k = 0; k < 3; k++) verts[3 * nv + k] = v[k];
            nv++;
        }
    }
    double volume = 0.0, centroid[3];
    int has_centroid = 0;
    if (nv > 0) {
        double s0 = 0.0, s1 = 0.0, s2 = 0.0;
        for (Py_ssize_t i = 0; i < nv; i++) {
            s0 += verts[3 * i];
            s1 += verts[3 * i + 1];
            s2 += verts[3 * i + 2];
        }
        double c0 = s0 / (double)nv, c1 = s1 / (double)nv, c2 = s2 / (double)nv;
        double m0 = 0.0, m1 = 0.0, m2 = 0.0;
        Py_ssize_t at = 0;
        for (Py_ssize_t f = 0; f < kept; f++) {
            const double *ring = faces + 3 * at;
            int n = face_n[f];
            at += n;
            double a0 = ring[0] - c0, a1 = ring[1] - c1, a2 = ring[2] - c2;
            for (int i = 1; i + 1 < n; i++) {
                const double *b = ring + 3 * i, *d = ring + 3 * (i + 1);
                double b0 = b[0] - c0, b1 = b[1] - c1, b2 = b[2] - c2;
                double d0 = d[0] - c0, d1 = d[1] - c1, d2 = d[2] - c2;
                double v = (a0 * (b1 * d2 - b2 * d1) + a1 * (b2 * d0 - b0 * d2) + a2 * (b0 * d1 - b1 * d0)) / 6;
                volume += v;
                m0 += v * (a0 + b0 + d0);
                m1 += v * (a1 + b1 + d1);
                m2 += v * (a2 + b2 + d2);
            }
        }
        if (volume != 0) {
            has_centroid = 1;
            centroid[0] = c0 + m0 / (4 * volume);
            centroid[1] = c1 + m1 / (4 * volume);
            centroid[2] = c2 + m2 / (4 * volume);
        }
    }
    PyObject *polygon = PyTuple_New(h);
    if (polygon == NULL)
        goto done;
    for (Py_ssize_t i = 0; i < h; i++) {
        PyObject *point = triple(plane + 3 * hull[i].point);
        if (point == NULL) {
            Py_DECREF(polygon);
            goto done;
        }
        PyTuple_SET_ITEM(polygon, i, point);
    }
    PyObject *c3 = has_centroid ? triple(centroid) : Py_NewRef(Py_None);
    PyObject *c2 = moments ? pair(cx + mx, cy + my) : Py_NewRef(Py_None);
    PyObject *tensor = moments ? Py_BuildValue("((dd)(dd))", J[0], J[1], J[1], J[2]) : Py_NewRef(Py_None);
    if (c3 && c2 && tensor)
        result = Py_BuildValue("(dOOdOO)", volume, c3, polygon, area, c2, tensor);
    Py_XDECREF(c3);
    Py_XDECREF(c2);
    Py_XDECREF(tensor);
    Py_DECREF(polygon);
done:
    free(faces); free(plane); free(verts); free(face_n); free(keys); free(hull); free(chain);
    PyBuffer_Release(&points);
    PyBuffer_Release(&sizes);
    return result;
}

static PyMethodDef methods[] = {
    {"volume_and_area", volume_and_area, METH_VARARGS,
     "volume_and_area(points, sizes, u0, u1, u2, t) -> (V, A): the volume below u . p = t and the waterplane's "
     "area of a packed float64 body (see symfloat.geometry.floating._volume_and_area)."},
    {"submerged", submerged, METH_VARARGS,
     "submerged(points, sizes, u0, u1, u2, t, e1, e2) -> (volume, centroid, polygon, area, plane centroid, tensor): "
     "the part of a packed float64 body below u . p = t (see symfloat.geometry.floating._submerged_part)."},
    {NULL, NULL, 0, NULL}
};

static struct PyModuleDef module = {PyModuleDef_HEAD_INIT, "_clipped", NULL, -1, methods};

PyMODINIT_FUNC
PyInit__clipped(void)
{
    return PyModule_Create(&module);
}
