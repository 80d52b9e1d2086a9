package org.trajeval.core.traj;

/** A coordinate plane poses can be projected onto. */
public enum Plane {
    /** The ground plane of z-up frames: z dropped, rotation kept about +z (yaw). */
    XY,
    /** The ground plane of camera frames (KITTI: y down): y dropped, rotation kept about +y. */
    XZ
}
