package org.trajeval.core.io;

/** What a reader does with two poses that carry the same timestamp. */
public enum DuplicateTimestamps {
    /** Refuse the file, naming both lines (default: a duplicate stamp usually means a logging fault). */
    REFUSE,
    /**
     * Keep both poses in file order, as evo does (its nearest matching then picks one of them by
     * its search rule; an interpolation across them uses the later one). The TUM fr2/desk ground
     * truth and the EuRoC V1_02 estimate shipped with evo contain such duplicates.
     */
    KEEP
}
