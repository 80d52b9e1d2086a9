package org.trajeval.core.io;

import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Catches timestamps written in another unit than the one declared: a time beyond
 * {@link #MAX_PLAUSIBLE_S} (about 3170 years) is not a robot's clock in seconds but almost
 * certainly epoch milli-, micro- or nanoseconds read as seconds. Epoch seconds (about 1.7e9 s)
 * pass.
 */
final class TimeUnitCheck {
    /** Largest plausible |time| (s): 1e11 s, about 3170 years. */
    static final double MAX_PLAUSIBLE_S = 1e11;

    private TimeUnitCheck() {
    }

    /** @return true if a time (s) is implausibly large */
    static boolean implausible(double seconds) {
        return Math.abs(seconds) > MAX_PLAUSIBLE_S;
    }

    /**
     * The refusal for a time that is implausibly large in the declared unit.
     *
     * @param stamp the stamp as read, in the declared unit
     * @param remedy what to do, given the unit it looks like, e.g. "pass --time-unit %s"
     */
    static InputException refuse(String source, long line, String column, double stamp, TimeUnit declared,
            String remedyFormat, String found) {
        TimeUnit looksLike = null;
        for (TimeUnit u : TimeUnit.values()) {
            if (u.perSecond() > declared.perSecond() && Math.abs(stamp / u.perSecond()) <= MAX_PLAUSIBLE_S) {
                looksLike = u;
                break;
            }
        }
        String seconds = String.format(java.util.Locale.ROOT, "%.3g", declared.toSeconds(stamp));
        String detail = "column '" + column + "' must be a time in " + declared.id() + ", but " + seconds
                + " s is more than " + (long) (MAX_PLAUSIBLE_S / 3.15576e7) + " years"
                + (looksLike == null ? "; no time unit makes it plausible"
                        : ": the stamps look like " + longName(looksLike) + ", " + String.format(remedyFormat, looksLike.id()));
        return new InputException(source, line, column, InputProblem.SUSPICIOUS_TIME_UNIT, detail, found);
    }

    private static String longName(TimeUnit u) {
        return switch (u) {
            case S -> "seconds (s)";
            case MS -> "milliseconds (ms)";
            case US -> "microseconds (us)";
            case NS -> "nanoseconds (ns)";
        };
    }
}
