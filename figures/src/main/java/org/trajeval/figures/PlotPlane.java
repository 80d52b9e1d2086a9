package org.trajeval.figures;

/**
 * The plane a trajectory is drawn in. {@link #AUTO} picks the two axes along which the reference
 * extends furthest, so a KITTI drive (camera frame: x right, y down, z forward) is drawn in x-z
 * rather than collapsed into a flat band in x-y.
 */
public enum PlotPlane {
    AUTO(-1, -1), XY(0, 1), XZ(0, 2), YZ(1, 2);

    private final int horizontal;
    private final int vertical;

    PlotPlane(int horizontal, int vertical) {
        this.horizontal = horizontal;
        this.vertical = vertical;
    }

    /** @return index (0 = x, 1 = y, 2 = z) of the horizontal axis */
    public int horizontal() {
        return horizontal;
    }

    /** @return index of the vertical axis */
    public int vertical() {
        return vertical;
    }

    /** @return axis name, "x", "y" or "z" */
    static String name(int axis) {
        return "xyz".substring(axis, axis + 1);
    }

    /**
     * @param x reference x (m), likewise y and z
     * @return this plane, or for AUTO the plane of the two largest extents (max - min), in axis order
     */
    public PlotPlane resolve(double[] x, double[] y, double[] z) {
        if (this != AUTO) {
            return this;
        }
        double ex = extent(x);
        double ey = extent(y);
        double ez = extent(z);
        if (ez <= ex && ez <= ey) {
            return XY;
        }
        return ey <= ex ? XZ : YZ;
    }

    private static double extent(double[] v) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double d : v) {
            if (Double.isFinite(d)) {
                lo = Math.min(lo, d);
                hi = Math.max(hi, d);
            }
        }
        return hi >= lo ? hi - lo : 0.0;
    }
}
