package org.trajeval.pipeline;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** Chooses the scorer of the end-to-end tests: the real core engine once it is merged. */
public final class TestScorers {
    private TestScorers() {
    }

    /** @return whether the core readers and engine are implemented (probed on a small pair) */
    public static boolean coreAvailable() {
        Path dir = null;
        try {
            dir = Files.createTempDirectory("trajeval-probe");
            Fixtures.writeTrajectory(dir.resolve("a.csv"), 50, 0.0, 1);
            Fixtures.writeTrajectory(dir.resolve("b.csv"), 50, 0.05, 2);
            new CoreRunScorer(1 << 20).score(new RunJob(RunMetadata.ofName("probe"), dir.resolve("a.csv"),
                    dir.resolve("b.csv"), org.trajeval.core.options.SettingValues.DEFAULTS, "probe"));
            return true;
        } catch (UnsupportedOperationException e) {
            return false;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } finally {
            try {
                if (dir != null) {
                    Fixtures.deleteTree(dir);
                }
            } catch (IOException ignored) {
                // a temporary folder
            }
        }
    }

    /** @return the real scorer when the core is merged, else the stand-in (with a loud warning) */
    public static RunScorer realOrStandIn() {
        if (coreAvailable()) {
            return new CoreRunScorer(256L << 20);
        }
        System.err.println("WARNING: core readers/engine not merged yet: pipeline end-to-end tests use StandInScorer");
        return new StandInScorer();
    }
}
