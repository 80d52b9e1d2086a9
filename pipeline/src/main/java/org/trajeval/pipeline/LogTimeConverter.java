package org.trajeval.pipeline;

import ch.qos.logback.classic.pattern.ClassicConverter;
import ch.qos.logback.classic.spi.ILoggingEvent;
import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.Locale;

/**
 * Logback's {@code %isotime}: a log line's time as {@code %d{yyyy-MM-dd'T'HH:mm:ss.SSSXXX}} writes it
 * ({@code 2026-11-26T00:39:34.356Z}, the JVM's default zone and locale, as logback's date converter),
 * formatted through {@link DateTimeFormatter} once per second instead of once per millisecond: the
 * date, time and offset of the second are kept and the milliseconds appended. The text is the same
 * because a pattern prints its fields in turn, and an offset changes only at a whole second.
 */
public final class LogTimeConverter extends ClassicConverter {
    private final DateTimeFormatter upToSeconds;
    private final DateTimeFormatter offset;
    private volatile Second cached = new Second(Long.MIN_VALUE, null, null);

    /** The second last formatted: its text up to the seconds' point, and its offset. */
    private record Second(long epochSecond, String upToPoint, String offset) {
    }

    /** In the JVM's default zone and locale, as logback's {@code %d}. */
    public LogTimeConverter() {
        this(ZoneId.systemDefault(), Locale.getDefault());
    }

    LogTimeConverter(ZoneId zone, Locale locale) {
        upToSeconds = DateTimeFormatter.ofPattern("yyyy-MM-dd'T'HH:mm:ss.").withZone(zone).withLocale(locale);
        offset = DateTimeFormatter.ofPattern("XXX").withZone(zone).withLocale(locale);
    }

    @Override
    public String convert(ILoggingEvent event) {
        return format(event.getTimeStamp());
    }

    /** @return the time {@code epochMillis} (ms since 1970-01-01T00:00Z) as the pattern above writes it */
    String format(long epochMillis) {
        long s = Math.floorDiv(epochMillis, 1000L);
        int ms = (int) Math.floorMod(epochMillis, 1000L);
        Second c = cached;
        if (c.epochSecond() != s) {
            Instant at = Instant.ofEpochSecond(s);
            c = new Second(s, upToSeconds.format(at), offset.format(at));
            cached = c;
        }
        StringBuilder b = new StringBuilder(c.upToPoint().length() + 3 + c.offset().length());
        b.append(c.upToPoint());
        if (ms < 100) {
            b.append(ms < 10 ? "00" : "0");
        }
        return b.append(ms).append(c.offset()).toString();
    }
}
