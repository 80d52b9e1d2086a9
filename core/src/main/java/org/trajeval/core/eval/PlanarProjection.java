package org.trajeval.core.eval;

/** Whether and when SE(3) poses are projected onto the ground plane. */
public enum PlanarProjection {
    /** Keep full SE(3). */
    NONE,
    /** Project onto xy before alignment (the lesson's SE(2) setting; {@code --planar}). */
    XY_BEFORE_ALIGNMENT,
    /** Project onto xy after a 3D alignment (evo's {@code --project_to_plane xy}). */
    XY_AFTER_ALIGNMENT,
    /**
     * Project onto xz after a 3D alignment (evo's {@code --project_to_plane xz}, for camera frames
     * such as KITTI's; headings beyond +-90 deg fold, as in evo).
     */
    XZ_AFTER_ALIGNMENT
}
