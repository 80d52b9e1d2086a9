package org.trajeval.pipeline.bundle;

/** The shapes a run bundle can take in incoming/. */
public enum BundleKind {
    /** A folder holding run.yaml and the trajectory files. */
    FOLDER,
    /** A .zip holding run.yaml (at its root or in one top-level folder) and the trajectory files. */
    ZIP,
    /** A bare pair {@code NAME.gt.csv} + {@code NAME.est.csv}; the run id is NAME. */
    PAIR,
    /** A bare bag {@code NAME.mcap}, {@code NAME.bag} or {@code NAME.db3} ({@link BareBag}); the run id is NAME. */
    BAG
}
