package org.trajeval.core.eval;

/** A named preset of evaluation rules; explicit options override a preset. */
public enum Convention {
    /**
     * The lesson's rules (default): reference interpolated at the estimate stamps, crop to the
     * overlap, se2/se3 alignment applied to whole poses, RPE over delta = 1 s with j the first
     * sample at or after t_i + delta.
     */
    LESSON,
    /** evo's rules: nearest association within 0.01 s, RPE delta 1 frame, no alignment unless asked. */
    EVO,
    /** KITTI's rules: poses paired by index, length-normalised drift as the headline. */
    KITTI
}
