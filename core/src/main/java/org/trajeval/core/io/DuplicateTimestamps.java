package org.trajeval.core.io;

/**
 * What a reader does with two poses that have the same timestamp. Real files have them (the TUM
 * RGB-D ground truth fr2_desk repeats one stamp, the EuRoC V102 estimate four); evo keeps them
 * and its association then takes the first of equal stamps.
 */
public enum DuplicateTimestamps {
    /** Refuse the file, naming both lines (default). */
    REFUSE,
    /** Keep both poses, in file order (as evo does); needed to reproduce evo's numbers on such files. */
    KEEP
}
