package org.trajeval.cli;

import java.util.Locale;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/**
 * Converters for numeric options that size an allocation or a pool, or must lie in a range: the
 * value is checked as it is parsed, so picocli's refusal names the option and the value found
 * ({@code Invalid value for option '--resamples': ...}) and no allocation is ever attempted.
 */
final class BoundedOptions {
    /** Largest bootstrap resample count (one double per resample per comparison: 8 MB). */
    static final int MAX_RESAMPLES = 1_000_000;
    /** Largest thread count of any command. */
    static final int MAX_THREADS = 256;

    private BoundedOptions() {
    }

    static long whole(String text, long min, long max, String what) {
        long v;
        try {
            v = Long.parseLong(text.trim());
        } catch (NumberFormatException e) {
            throw new TypeConversionException("must be a whole number of " + what + " from " + min + " to " + max
                    + ", found \"" + text + "\"");
        }
        if (v < min || v > max) {
            throw new TypeConversionException("must be a whole number of " + what + " from " + min + " to " + max
                    + ", found " + text.trim());
        }
        return v;
    }

    /** {@code --confidence}: a level strictly between 0 and 1. */
    static final class Confidence implements ITypeConverter<Double> {
        @Override
        public Double convert(String text) {
            double v;
            try {
                v = Double.parseDouble(text.trim());
            } catch (NumberFormatException e) {
                v = Double.NaN;
            }
            if (!(v > 0 && v < 1)) {
                throw new TypeConversionException(String.format(Locale.ROOT,
                        "must be a level between 0 and 1 (exclusive), e.g. 0.95, found \"%s\"", text));
            }
            return v;
        }
    }

    /** {@code --resamples}: 100 to {@link #MAX_RESAMPLES}. */
    static final class Resamples implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            return (int) whole(text, 100, MAX_RESAMPLES, "bootstrap resamples");
        }
    }

    /** {@code --threads}: 1 to {@link #MAX_THREADS}. */
    static final class Threads implements ITypeConverter<Integer> {
        @Override
        public Integer convert(String text) {
            return (int) whole(text, 1, MAX_THREADS, "threads");
        }
    }
}
