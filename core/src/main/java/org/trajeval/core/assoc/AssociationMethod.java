package org.trajeval.core.assoc;

/** How poses of the estimate are paired with poses of the reference in time. */
public enum AssociationMethod {
    /**
     * The lesson's rule: the reference is interpolated at the estimate's timestamps (positions
     * linearly, planar yaw through sin/cos, SE(3) rotations by slerp).
     */
    INTERPOLATE,
    /**
     * evo's rule: for each pose of the shorter trajectory the nearest stamp of the longer one,
     * if within the max difference (inclusive; ties to the earlier stamp; not one-to-one).
     */
    NEAREST,
    /**
     * evo's {@code --sync_method interpolation}: the poses of the shorter trajectory that have a
     * nearest partner within the max difference are kept, and the longer trajectory is
     * interpolated at exactly their timestamps.
     */
    NEAREST_INTERPOLATED
}
