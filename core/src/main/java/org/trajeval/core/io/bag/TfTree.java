package org.trajeval.core.io.bag;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.geom.Rotations;

/**
 * The TF tree of a bag: one edge per child frame (its parent, and either a static transform or a
 * time series of transforms, child frame expressed in the parent frame), and lookups of the
 * transform between two frames at a time, as tf2 does them without ROS: each edge interpolated
 * between the two stamps around the asked time (linear in translation, slerp in rotation; the
 * exact sample when the time is one of its stamps), static edges valid at all times, no
 * extrapolation.
 */
final class TfTree {
    /** One edge parent -> child. */
    static final class Edge {
        final String parent;
        final String child;
        final boolean isStatic;
        final PoseColumns series = new PoseColumns();

        Edge(String parent, String child, boolean isStatic) {
            this.parent = parent;
            this.child = child;
            this.isStatic = isStatic;
        }
    }

    private final String source;
    private final Map<String, Edge> byChild = new LinkedHashMap<>();

    TfTree(String source) {
        this.source = source;
    }

    /** tf2 drops a leading slash of frame ids. */
    static String frame(String id) {
        return id != null && id.startsWith("/") ? id.substring(1) : id == null ? "" : id;
    }

    /**
     * Adds one transform.
     *
     * @param v the slots of {@link PosePlan} (stamp, translation, rotation)
     * @throws InputException when a child frame gets a second parent
     */
    void add(String parentId, String childId, boolean isStatic, double[] v) {
        String parent = frame(parentId);
        String child = frame(childId);
        Edge e = byChild.get(child);
        if (e == null) {
            e = new Edge(parent, child, isStatic);
            byChild.put(child, e);
        } else if (!e.parent.equals(parent)) {
            throw new InputException(source, 0, child, InputProblem.CORRUPT_BAG, "TF frame '" + child
                    + "' has two parents, '" + e.parent + "' and '" + parent + "'; a TF tree gives each frame one",
                    parent);
        }
        double t = v[PosePlan.SEC] + v[PosePlan.NSEC] * 1e-9;
        if (e.isStatic || isStatic) {
            e.series.clear(); // static: the latest value holds for all times
        }
        e.series.add(t, v[PosePlan.X], v[PosePlan.Y], v[PosePlan.Z], v[PosePlan.QW], v[PosePlan.QX],
                v[PosePlan.QY], v[PosePlan.QZ]);
    }

    /** Sorts each dynamic edge by stamp; of equal stamps the first one received stays (tf2 keeps it). */
    void finish() {
        for (Edge e : byChild.values()) {
            PoseColumns c = e.series;
            if (e.isStatic || c.n < 2) {
                continue;
            }
            Integer[] idx = new Integer[c.n];
            for (int i = 0; i < c.n; i++) {
                idx[i] = i;
            }
            double[] t = c.t;
            Arrays.sort(idx, (a, b) -> Double.compare(t[a], t[b]));
            int[] keep = new int[c.n];
            int k = 0;
            for (int i = 0; i < c.n; i++) {
                if (k == 0 || t[idx[i]] != t[keep[k - 1]]) {
                    keep[k++] = idx[i];
                }
            }
            double[][] d = c.columns(Arrays.copyOf(keep, k));
            c.t = d[0];
            c.x = d[1];
            c.y = d[2];
            c.z = d[3];
            c.qw = d[4];
            c.qx = d[5];
            c.qy = d[6];
            c.qz = d[7];
            c.n = k;
        }
    }

    /** @return every frame, sorted */
    TreeSet<String> frames() {
        TreeSet<String> f = new TreeSet<>();
        for (Edge e : byChild.values()) {
            f.add(e.parent);
            f.add(e.child);
        }
        return f;
    }

    Map<String, Edge> edges() {
        return byChild;
    }

    /**
     * The edges from {@code parent} down to {@code child}: the first list climbs from parent to the
     * common ancestor (to be inverted), the second descends from the common ancestor to the child.
     */
    List<List<Edge>> path(String parent, String child, String id) {
        for (String f : new String[] {parent, child}) {
            if (!frames().contains(f)) {
                throw new InputException(source, 0, id, InputProblem.UNKNOWN_TOPIC, "TF frame '" + f
                        + "' does not exist in the bag; its frames are: " + String.join(", ", frames()), f);
            }
        }
        List<String> up = ancestors(parent);
        List<String> down = ancestors(child);
        String common = null;
        for (String a : down) {
            if (up.contains(a)) {
                common = a;
                break;
            }
        }
        if (common == null) {
            throw new InputException(source, 0, id, InputProblem.UNKNOWN_TOPIC, "TF frames '" + parent + "' and '"
                    + child + "' are in different trees (roots '" + up.get(up.size() - 1) + "' and '"
                    + down.get(down.size() - 1) + "'): no transform between them", id);
        }
        List<Edge> climb = new ArrayList<>();
        for (String f = parent; !f.equals(common); f = byChild.get(f).parent) {
            climb.add(byChild.get(f));
        }
        List<Edge> descend = new ArrayList<>();
        for (String f = child; !f.equals(common); f = byChild.get(f).parent) {
            descend.add(0, byChild.get(f));
        }
        return List.of(climb, descend);
    }

    private List<String> ancestors(String f) {
        List<String> out = new ArrayList<>();
        String cur = f;
        while (cur != null && !out.contains(cur)) {
            out.add(cur);
            Edge e = byChild.get(cur);
            cur = e == null ? null : e.parent;
        }
        if (cur != null) {
            throw new InputException(source, 0, f, InputProblem.CORRUPT_BAG, "the TF frames above '" + f
                    + "' form a loop (" + String.join(" -> ", out) + " -> " + cur + ")", cur);
        }
        return out;
    }

    /**
     * The transform of one edge at time t: {@code out} = (x, y, z, qw, qx, qy, qz).
     *
     * @return false when t lies outside the edge's stamps (no extrapolation)
     */
    static boolean at(Edge e, double t, double[] out) {
        PoseColumns c = e.series;
        if (e.isStatic) {
            copy(c, c.n - 1, out);
            return true;
        }
        int hi = Arrays.binarySearch(c.t, 0, c.n, t);
        if (hi >= 0) {
            copy(c, hi, out);
            return true;
        }
        hi = -hi - 1;
        if (hi == 0 || hi == c.n) {
            return false;
        }
        int lo = hi - 1;
        double r = (t - c.t[lo]) / (c.t[hi] - c.t[lo]);
        double s = 1.0 - r;
        out[0] = s * c.x[lo] + r * c.x[hi];
        out[1] = s * c.y[lo] + r * c.y[hi];
        out[2] = s * c.z[lo] + r * c.z[hi];
        double[] q = new double[4];
        Rotations.slerp(new double[] {c.qw[lo], c.qx[lo], c.qy[lo], c.qz[lo]},
                new double[] {c.qw[hi], c.qx[hi], c.qy[hi], c.qz[hi]}, r, q);
        System.arraycopy(q, 0, out, 3, 4);
        return true;
    }

    private static void copy(PoseColumns c, int i, double[] out) {
        out[0] = c.x[i];
        out[1] = c.y[i];
        out[2] = c.z[i];
        out[3] = c.qw[i];
        out[4] = c.qx[i];
        out[5] = c.qy[i];
        out[6] = c.qz[i];
    }

    /** a = a * b for poses (x, y, z, qw, qx, qy, qz): t = t_a + R_a t_b, q = q_a q_b. */
    static void compose(double[] a, double[] b) {
        double[] r = new double[9];
        Rotations.fromQuaternion(a[3], a[4], a[5], a[6], r, 0);
        double x = a[0] + r[0] * b[0] + r[1] * b[1] + r[2] * b[2];
        double y = a[1] + r[3] * b[0] + r[4] * b[1] + r[5] * b[2];
        double z = a[2] + r[6] * b[0] + r[7] * b[1] + r[8] * b[2];
        double w = a[3] * b[3] - a[4] * b[4] - a[5] * b[5] - a[6] * b[6];
        double qx = a[3] * b[4] + a[4] * b[3] + a[5] * b[6] - a[6] * b[5];
        double qy = a[3] * b[5] - a[4] * b[6] + a[5] * b[3] + a[6] * b[4];
        double qz = a[3] * b[6] + a[4] * b[5] - a[5] * b[4] + a[6] * b[3];
        a[0] = x;
        a[1] = y;
        a[2] = z;
        a[3] = w;
        a[4] = qx;
        a[5] = qy;
        a[6] = qz;
    }

    /** p = p^-1: q' = conj(q) / |q|^2, t' = -R^T t. */
    static void invert(double[] p) {
        double[] r = new double[9];
        Rotations.fromQuaternion(p[3], p[4], p[5], p[6], r, 0);
        double x = -(r[0] * p[0] + r[3] * p[1] + r[6] * p[2]);
        double y = -(r[1] * p[0] + r[4] * p[1] + r[7] * p[2]);
        double z = -(r[2] * p[0] + r[5] * p[1] + r[8] * p[2]);
        double n2 = p[3] * p[3] + p[4] * p[4] + p[5] * p[5] + p[6] * p[6];
        p[0] = x;
        p[1] = y;
        p[2] = z;
        p[3] = p[3] / n2;
        p[4] = -p[4] / n2;
        p[5] = -p[5] / n2;
        p[6] = -p[6] / n2;
    }
}
