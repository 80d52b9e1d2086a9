package org.trajeval.cli;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.InputBytes;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.ReportJson;

/**
 * Warm-up of a cold {@code trajeval eval} on the second core: while the main thread builds and
 * parses picocli's command line (about a third of a 10^4-pose run, on one core), a daemon thread
 * reads, evaluates and writes as JSON a small generated pair held in memory ({@value #POSES}
 * poses; planar CSV with the lesson's options when REF ends in {@code .csv}, else TUM with evo's
 * SE(3) alignment). The classes of reading, evaluation and report are then loaded and
 * initialised, their method handles and annotation proxies made, and their hot methods profiled
 * or compiled before the real pair is read. Nothing of it is kept, written or printed; the real
 * evaluation starts only once it is over ({@link #awaitStarted()}), so the two never run side by
 * side, and a failure of the warm-up is ignored (the real run reports its own). A command refused
 * before reading (a usage error, a missing file) does not wait for it.
 */
final class EvalWarmUp {
    /** Poses of each generated file. */
    static final int POSES = 1000;

    private static volatile Thread running;

    private EvalWarmUp() {
    }

    /**
     * Starts the warm-up for the launcher's arguments when they are an {@code eval} of a planar CSV
     * pair or of a 3D pair with {@code --convention evo} (the path the 3D warm-up trains), a second
     * processor is available (on one, the warm-up would only delay the main thread) and
     * {@code --threads 1} (everything on one thread) is not given (nor an argument file, which may give it).
     */
    static void startFor(String[] args) {
        if (args.length < 2 || !args[0].equals("eval") || Runtime.getRuntime().availableProcessors() < 2
                || gives(args, "--threads", EvalWarmUp::isOne) || readsAnArgumentFile(args)) {
            return;
        }
        boolean planar = args[1].toLowerCase(java.util.Locale.ROOT).endsWith(".csv");
        if (!planar && !gives(args, "--convention", "evo"::equals)) {
            // the 3D warm-up trains evo's path (nearest matching, SE(3)); for another convention it
            // cost a 10^6-pose lesson pair on two threads 0.2-0.3 s of CPU and gained nothing
            return;
        }
        Thread t = new Thread(() -> {
            try {
                run(planar);
            } catch (RuntimeException | Error e) {
                // the real run reads, evaluates and reports on its own, with its own errors
            }
        }, "trajeval-warm-up");
        t.setDaemon(true);
        running = t;
        t.start();
    }

    /** @return whether {@code args} give {@code option} a value {@code wanted} accepts, as "OPTION VALUE" or "OPTION=VALUE" */
    private static boolean gives(String[] args, String option, java.util.function.Predicate<String> wanted) {
        for (int i = 1; i < args.length; i++) {
            if (args[i].startsWith(option + "=") && wanted.test(args[i].substring(option.length() + 1))
                    || args[i].equals(option) && i + 1 < args.length && wanted.test(args[i + 1])) {
                return true;
            }
        }
        return false;
    }

    /**
     * @return whether picocli reads more arguments from a file ({@code @FILE}): what they say (a
     *     {@code --threads 1}) is not known here, so no warm-up is started
     */
    private static boolean readsAnArgumentFile(String[] args) {
        for (String a : args) {
            if (a.startsWith("@")) {
                return true;
            }
        }
        return false;
    }

    /** @return whether {@code --threads} reads {@code text} as 1 ({@link BoundedOptions#whole}: "01", " 1", "+1") */
    private static boolean isOne(String text) {
        try {
            return Long.parseLong(text.trim()) == 1;
        } catch (NumberFormatException e) {
            return false;
        }
    }

    /** @return whether a warm-up was started and not yet waited for */
    static boolean pending() {
        return running != null;
    }

    /** Waits until a started warm-up is over (returns at once when none was started). */
    static void awaitStarted() {
        Thread t = running;
        if (t == null) {
            return;
        }
        running = null;
        boolean interrupted = false;
        while (true) {
            try {
                t.join();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    /**
     * Reads, evaluates and formats one generated pair, as an eval of such files would.
     *
     * @param planar a planar CSV pair with the lesson's options, or a TUM pair with evo's SE(3)
     * @return the report's JSON text
     */
    static String run(boolean planar) {
        List<SettingText> given = planar
                ? List.of(setting("convention", "lesson"), setting("association", "interpolate"),
                        setting("alignment", "se2"), setting("rpe_delta", "1"), setting("rpe_unit", "s"))
                : List.of(setting("convention", "evo"), setting("alignment", "se3"));
        SettingValues settings = SettingValues.of(given, null);
        ReadOptions limits = ReadOptions.defaults();
        LoadedTrajectory ref = TrajectoryReader.read(bytes(planar ? "warm-up-ref.csv" : "warm-up-ref.tum",
                pair(planar, false)), SettingsResolver.readOptions(settings, FileRole.REFERENCE, limits,
                PathResolver.asWritten()));
        LoadedTrajectory est = TrajectoryReader.read(bytes(planar ? "warm-up-est.csv" : "warm-up-est.tum",
                pair(planar, true)), SettingsResolver.readOptions(settings, FileRole.ESTIMATE, limits,
                PathResolver.asWritten()));
        return ReportJson.toJson(Evaluator.evaluate(ref, est, SettingsResolver.evaluationOptions(settings,
                DataKind.of(ref.trajectory(), est.trajectory()))));
    }

    private static SettingText setting(String key, String value) {
        return new SettingText(key, value, "warm-up");
    }

    private static InputBytes bytes(String name, String text) {
        byte[] b = text.getBytes(StandardCharsets.US_ASCII);
        return InputBytes.read(name, () -> new ByteArrayInputStream(b), b.length);
    }

    /**
     * One file of the pair: 100 Hz on a circle of 30 m; the estimate 3 ms later, turned by 0.3 rad,
     * shifted by (-4, -3) m and drifting, numbers written with 6 (yaw, quaternion: 9) decimals.
     */
    static String pair(boolean planar, boolean estimate) {
        StringBuilder s = new StringBuilder(POSES * 80);
        if (planar) {
            s.append("t,x,y,yaw\n");
        }
        char sep = planar ? ',' : ' ';
        for (int i = 0; i < POSES; i++) {
            double a = 0.01 * i;
            double t = 1000.0 + 0.01 * i + (estimate ? 0.003 : 0.0);
            double x = 30 * Math.sin(a);
            double y = 30 * Math.cos(a);
            double yaw = -a;
            if (estimate) {
                double c = Math.cos(0.3);
                double sn = Math.sin(0.3);
                double drift = 1e-3 * i;
                double xr = c * x - sn * y - 4 + drift;
                y = sn * x + c * y - 3 + 0.5 * drift;
                x = xr;
                yaw += 0.3;
            }
            fixed(s, t, 6).append(sep);
            fixed(s, x, 6).append(sep);
            fixed(s, y, 6).append(sep);
            if (planar) {
                fixed(s, yaw, 9);
            } else {
                s.append("0.0 0.0 0.0 ");
                fixed(s, Math.sin(yaw / 2), 9).append(' ');
                fixed(s, Math.cos(yaw / 2), 9);
            }
            s.append('\n');
        }
        return s.toString();
    }

    /** Appends {@code v} rounded to {@code decimals} places (at most 9), without a format string. */
    static StringBuilder fixed(StringBuilder s, double v, int decimals) {
        long scale = 1;
        for (int i = 0; i < decimals; i++) {
            scale *= 10;
        }
        long units = Math.round(Math.abs(v) * scale);
        if (v < 0) {
            s.append('-');
        }
        s.append(units / scale).append('.');
        String frac = Long.toString(units % scale);
        for (int i = frac.length(); i < decimals; i++) {
            s.append('0');
        }
        return s.append(frac);
    }
}
