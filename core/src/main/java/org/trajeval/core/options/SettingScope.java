package org.trajeval.core.options;

/** What a setting acts on: reading one or both files, or the evaluation of the pair. */
public enum SettingScope {
    /** Reading both files. */
    READ_BOTH,
    /** Reading the reference only. */
    READ_REFERENCE,
    /** Reading the estimate only. */
    READ_ESTIMATE,
    /** The evaluation (association, alignment, metrics). */
    EVALUATION
}
