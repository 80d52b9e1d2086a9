package org.trajeval.cli;

import java.io.PrintWriter;
import java.time.Clock;
import java.util.ArrayList;
import java.util.List;
import org.trajeval.store.Labels;
import org.trajeval.store.ReportRecords;
import org.trajeval.store.ResultsStore;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * {@code eval --db URL [--tag K=V ...]}: records the evaluation in the results store, the row
 * {@code db import} makes of the same report ({@link ReportRecords#fromEvaluation}), so re-running
 * the same evaluation, or importing its {@code --out} file, adds nothing.
 */
final class EvalRecording {
    @Mixin
    StoreOptions store = new StoreOptions();

    @Option(names = "--tag", paramLabel = "KEY=VALUE", description = {"With --db: label the stored result "
        + "(repeatable): software_version, robot, site, route, method, seed fill their columns, other keys are "
        + "free tags, e.g. --tag software_version=2.4 --tag route=hall --tag shift=night."})
    List<String> tags = new ArrayList<>();

    /**
     * @return the labels, checked before anything is evaluated
     * @throws org.trajeval.core.InputException when --tag is given without --db
     */
    Labels labels() {
        if (!tags.isEmpty() && !store.given()) {
            throw UsageProblem.of("--tag labels the stored result: it needs --db");
        }
        return Labels.parse(tags, Labels.EVAL_COLUMNS);
    }

    /** @return whether --db was given */
    boolean wanted() {
        return store.given();
    }

    /**
     * @param reportJson the evaluation report's JSON text
     * @param source the report file, or the two inputs, for the row's source
     */
    void record(String reportJson, String source, Labels labels, Clock clock, PrintWriter err) {
        try (ResultsStore s = store.open()) {
            int n = s.record(List.of(ReportRecords.fromEvaluation(reportJson, source, clock.instant(), labels)));
            err.println("trajeval: " + (n == 1 ? "recorded the result in " : "the result was already in ")
                    + s.location());
        }
        err.flush();
    }
}
