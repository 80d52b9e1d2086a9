package org.trajeval.cli;

import java.io.PrintWriter;
import org.trajeval.core.protocol.SuiteRunner;

/**
 * A one-line progress bar on the terminal ({@code [#####.....] 45/120 runs}), redrawn in place
 * with a carriage return. Only used when the output is a terminal and the suite has many runs.
 */
final class ProgressBar implements SuiteRunner.Progress {
    /** Suites with fewer runs get no bar. */
    static final int MIN_RUNS = 10;
    private static final int WIDTH = 30;

    private final PrintWriter err;
    private int lastDrawn = -1;

    ProgressBar(PrintWriter err) {
        this.err = err;
    }

    /** @return a bar when stderr is a terminal and there are enough runs to matter, else nothing */
    static SuiteRunner.Progress forTerminal(PrintWriter err) {
        return System.console() != null ? new ProgressBar(err) : SuiteRunner.Progress.none();
    }

    /**
     * @param what what is counted ("figures", "results")
     * @return a bar over any count when stderr is a terminal, else nothing (never in pipes)
     */
    static org.trajeval.figures.FigurePage.Progress counter(PrintWriter err, String what) {
        if (System.console() == null) {
            return org.trajeval.figures.FigurePage.Progress.none();
        }
        ProgressBar bar = new ProgressBar(err);
        return (done, total) -> bar.draw(done, total, what);
    }

    @Override
    public synchronized void runFinished(int done, int total) {
        if (total < MIN_RUNS) {
            return;
        }
        draw(done, total, "runs");
    }

    private synchronized void draw(int done, int total, String what) {
        int filled = (int) ((long) WIDTH * done / total);
        if (filled == lastDrawn && done != total) {
            return;
        }
        lastDrawn = filled;
        err.print("\r[" + "#".repeat(filled) + ".".repeat(WIDTH - filled) + "] " + done + "/" + total + " " + what);
        if (done == total) {
            err.print("\r" + " ".repeat(WIDTH + 30) + "\r");
        }
        err.flush();
    }
}
