package org.trajeval.core;

/** What is wrong with an input, one constant per kind of refusal; tests assert on these. */
public enum InputProblem {
    /** The file could not be opened or read. */
    UNREADABLE,
    /** The file holds no data rows. */
    EMPTY,
    /** A required column is missing from the header. */
    MISSING_COLUMN,
    /** A column name appears twice: in the header, or among the configured names (which would read one column twice). */
    DUPLICATE_COLUMN,
    /** A row has fewer or more fields than the format needs. */
    WRONG_FIELD_COUNT,
    /** A field is not a number. */
    NOT_A_NUMBER,
    /** A field is NaN or infinite. */
    NOT_FINITE,
    /** A timestamp is smaller than the one before it. */
    DECREASING_TIMESTAMP,
    /** A timestamp equals the one before it. */
    DUPLICATE_TIMESTAMP,
    /** A quaternion's norm differs from 1 by more than the tolerance. */
    NON_UNIT_QUATERNION,
    /** A rotation matrix is not orthonormal within the tolerance. */
    NOT_A_ROTATION,
    /** Fewer poses than the metric or alignment needs. */
    TOO_FEW_POSES,
    /** The two trajectories share no time interval, or no stamps within the max difference. */
    NO_OVERLAP,
    /** Poses fall outside the other trajectory's time span and the overlap policy is strict. */
    OUTSIDE_OVERLAP,
    /** Timestamps look like another unit than the one configured (e.g. ns read as s). */
    SUSPICIOUS_TIME_UNIT,
    /** The format could not be recognised. */
    UNKNOWN_FORMAT,
    /** Text that is not UTF-8 (UTF-16, Latin-1, binary); the message names the encoding seen and where. */
    NOT_UTF8,
    /** The alignment problem is degenerate (e.g. collinear or coincident points). */
    DEGENERATE_ALIGNMENT,
    /** An option value is out of its allowed range or inconsistent with another. */
    INVALID_OPTION,
    /** A value lies beyond its documented bound (a position beyond 1e9 m). */
    OUT_OF_RANGE,
    /** The input exceeds a configured size or pose limit. */
    TOO_LARGE,
    /** A manifest or configuration key is unknown, missing or inconsistent. */
    INVALID_CONFIGURATION,
    /** A path points outside the folder it must stay in. */
    PATH_ESCAPES,
    /** A bag's bytes contradict its own structure: bad magic or CRC, a length past the end, a chunk that lies. */
    CORRUPT_BAG,
    /** A bag uses a feature trajeval does not read (compression, message or schema encoding). */
    UNSUPPORTED_BAG_FEATURE,
    /** The asked topic, TF frame or field does not exist in the bag, or holds no pose. */
    UNKNOWN_TOPIC
}
