package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.report.ReportJson;

/**
 * The warm-up of a cold eval must really read, evaluate and report (its errors are swallowed in
 * the launcher, so a warm-up that silently failed would only cost time). Reference: the same
 * generated files written to disk and scored by {@code trajeval eval} with the options the warm-up
 * names: the whole JSON report, byte for byte, once the file names are the same.
 */
class EvalWarmUpTest {
    @TempDir
    Path dir;

    /** @return the report of {@code trajeval eval} on the warm-up's files, with the warm-up's file names */
    private String onCommandLine(boolean planar, String... options) throws IOException {
        String ext = planar ? ".csv" : ".tum";
        Path ref = Files.write(dir.resolve("ref" + ext), EvalWarmUp.pair(planar, false).getBytes(StandardCharsets.US_ASCII));
        Path est = Files.write(dir.resolve("est" + ext), EvalWarmUp.pair(planar, true).getBytes(StandardCharsets.US_ASCII));
        String[] args = new String[options.length + 4];
        args[0] = "eval";
        args[1] = ref.toString();
        args[2] = est.toString();
        System.arraycopy(options, 0, args, 3, options.length);
        args[args.length - 1] = "--json";
        CliRun run = CliRun.of(args);
        assertEquals(0, run.code(), run.err());
        return run.out().trim().replace(ref.toString(), "warm-up-ref" + ext).replace(est.toString(), "warm-up-est" + ext);
    }

    @Test
    void planarWarmUpScoresItsPairAsTheLessonEvalOfTheSameFiles() throws IOException {
        String warm = EvalWarmUp.run(true);
        assertEquals(onCommandLine(true, "--convention", "lesson", "--association", "interpolate", "--align",
                "se2", "--rpe-delta", "1", "--rpe-unit", "s"), warm);
        assertEquals(EvalWarmUp.POSES - 1, ReportJson.parseEvaluation(warm).association().matched(), "the last estimate pose is past the reference");
    }

    @Test
    void tumWarmUpScoresItsPairAsTheEvoSe3EvalOfTheSameFiles() throws IOException {
        String warm = EvalWarmUp.run(false);
        assertEquals(onCommandLine(false, "--convention", "evo", "--align", "se3"), warm);
        assertTrue(ReportJson.parseEvaluation(warm).ate().transM().n() > EvalWarmUp.POSES / 2, "most poses associated");
    }

    @Test
    void fixedDecimalsRoundTripThroughParseDouble() {
        double[] values = {0, -0.0, 1e-7, -1e-7, 0.5, -0.5, 1000.003, -31.499999, 123456.7890123, 0.999999999, -2.5e-4};
        for (int d : new int[] {6, 9}) {
            for (double v : values) {
                String s = EvalWarmUp.fixed(new StringBuilder(), v, d).toString();
                assertEquals(d, s.length() - s.indexOf('.') - 1, s);
                assertEquals(v, Double.parseDouble(s), 0.5 * Math.pow(10, -d) * (1 + 1e-9), s);
            }
        }
    }

    @Test
    void noWarmUpForOtherCommandsAnEvalWithoutFilesOrOneThread() {
        for (String[] args : new String[][] {{"--version"}, {"suite", "run", "x.yaml"}, {"eval"},
            {"eval", "a.csv", "b.csv", "--threads", "1"}, {"eval", "a.csv", "b.csv", "--threads=1"},
            {"eval", "a.tum", "b.tum"}, {"eval", "a.tum", "b.tum", "--convention", "lesson"},
            {"eval", "a.tum", "b.tum", "--convention=kitti"}}) {
            EvalWarmUp.startFor(args);
            assertFalse(EvalWarmUp.pending(), String.join(" ", args));
        }
        EvalWarmUp.awaitStarted(); // nothing started: returns at once
    }

    @Test
    void aRefusedEvalDoesNotWaitForTheWarmUp() {
        // the call waited for the warm-up before anything else, so a typo in a path or a usage error was printed
        // only after the warm-up's evaluation (0.2-0.3 s of a cold start, rt9); the warm-up stays pending
        assumeTrue(Runtime.getRuntime().availableProcessors() >= 2, "without a second processor no warm-up starts");
        Path missing = dir.resolve("missing.csv");
        for (String[] args : new String[][] {{"eval", missing.toString(), missing.toString()},
            {"eval", missing.toString()}, {"eval", missing.toString(), missing.toString(), "--align", "nope"}}) {
            EvalWarmUp.startFor(args);
            assertTrue(EvalWarmUp.pending(), String.join(" ", args));
            CliRun run = CliRun.of(args);
            assertEquals(2, run.code(), run.err());
            assertTrue(EvalWarmUp.pending(), "waited for the warm-up: " + String.join(" ", args));
            EvalWarmUp.awaitStarted();
        }
    }

    @Test
    void oneThreadWrittenAsTheOptionReadsItStartsNoWarmUp() {
        // --threads reads its value as a whole number (BoundedOptions.whole: trimmed, Long.parseLong), so these
        // all ask for one thread; the warm-up compared the text with "1" and ran a second thread for them (rt9)
        assumeTrue(Runtime.getRuntime().availableProcessors() >= 2, "without a second processor no warm-up starts");
        for (String one : new String[] {"01", " 1", "+1", "1 ", "001"}) {
            assertEquals(1, new BoundedOptions.Threads().convert(one), one);
            for (String[] args : new String[][] {{"eval", "a.csv", "b.csv", "--threads", one},
                {"eval", "a.csv", "b.csv", "--threads=" + one}}) {
                EvalWarmUp.startFor(args);
                assertFalse(EvalWarmUp.pending(), String.join(" ", args));
            }
        }
        EvalWarmUp.awaitStarted();
    }

    @Test
    void anArgumentFileWhichMayAskForOneThreadStartsNoWarmUp() throws IOException {
        // picocli reads more arguments from @FILE (checked below: its --threads 1 is the run's); the warm-up cannot
        // see them, so it must not start (it ran on a second thread for such a run, rt9)
        assumeTrue(Runtime.getRuntime().availableProcessors() >= 2, "without a second processor no warm-up starts");
        Path options = Files.writeString(dir.resolve("options.txt"), "--threads\n1\n");
        String[] args = {"eval", "a.csv", "b.csv", "@" + options};
        try {
            EvalWarmUp.startFor(args);
            assertFalse(EvalWarmUp.pending(), String.join(" ", args));
        } finally {
            EvalWarmUp.awaitStarted(); // a wrongly started warm-up must not leak into the next test
        }
        Path bad = Files.writeString(dir.resolve("bad.txt"), "--threads\nzero\n");
        CliRun run = CliRun.of("eval", "a.csv", "b.csv", "@" + bad);
        assertTrue(run.err().contains("found \"zero\""), "picocli reads the file's arguments: " + run.err());
    }

    @Test
    void anEvalOnTwoProcessorsStartsTheWarmUpAndTheCallWaitsForIt() {
        assumeTrue(Runtime.getRuntime().availableProcessors() >= 2, "needs a second processor");
        EvalWarmUp.startFor(new String[] {"eval", "a.csv", "b.csv", "--threads", "2"});
        assertTrue(EvalWarmUp.pending());
        EvalWarmUp.awaitStarted();
        assertFalse(EvalWarmUp.pending());
        for (String[] args : new String[][] {{"eval", "a.tum", "b.tum", "--convention", "evo"},
            {"eval", "a.tum", "b.tum", "--convention=evo", "--align", "sim3"}}) {
            EvalWarmUp.startFor(args);
            assertTrue(EvalWarmUp.pending(), String.join(" ", args));
            EvalWarmUp.awaitStarted();
        }
    }
}
