package org.trajeval.pipeline.dir;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The service's folders under one root: {@code incoming/ -> processing/ -> done/ | failed/},
 * {@code reports/} (one RUN_ID.json per run) and {@code ledger/ledger.log}.
 *
 * @param root the root folder
 */
public record DirectoryLayout(Path root) {
    /** @param root the root folder (made absolute) */
    public DirectoryLayout {
        root = root.toAbsolutePath().normalize();
    }

    /** @return where bundles are dropped */
    public Path incoming() {
        return root.resolve("incoming");
    }

    /** @return where claimed bundles are processed */
    public Path processing() {
        return root.resolve("processing");
    }

    /** @return where processed bundles go */
    public Path done() {
        return root.resolve("done");
    }

    /** @return where refused bundles go, each with NAME.error.json */
    public Path failed() {
        return root.resolve("failed");
    }

    /** @return where reports are written */
    public Path reports() {
        return root.resolve("reports");
    }

    /** @return the ledger file */
    public Path ledger() {
        return root.resolve("ledger").resolve("ledger.log");
    }

    /** Creates every folder. */
    public DirectoryLayout create() {
        try {
            for (Path p : new Path[] {incoming(), processing(), done(), failed(), reports(), ledger().getParent()}) {
                Files.createDirectories(p);
            }
            return this;
        } catch (IOException e) {
            throw new UncheckedIOException("could not create the service folders under " + root + ": " + e.getMessage(), e);
        }
    }
}
