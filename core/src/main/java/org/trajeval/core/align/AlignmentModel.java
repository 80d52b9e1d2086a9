package org.trajeval.core.align;

/**
 * Which transform is fitted to bring the estimate onto the reference before ATE. The fitted
 * transform is applied to whole poses (positions and orientations).
 */
public enum AlignmentModel {
    /** No alignment. */
    NONE,
    /** Planar rigid motion: rotation about z and translation in xy (3 DoF). */
    SE2,
    /** Planar similarity: SE2 plus a scale factor (4 DoF). */
    SIM2,
    /** Rigid motion in 3D (Umeyama without scale, 6 DoF). */
    SE3,
    /** Similarity in 3D (Umeyama with scale, 7 DoF). */
    SIM3,
    /** The transform that maps the first estimate pose onto the first reference pose. */
    ORIGIN,
    /** Position plus yaw (4 DoF): rotation about z and a 3D translation, as for VIO / ground robots. */
    POSYAW
}
