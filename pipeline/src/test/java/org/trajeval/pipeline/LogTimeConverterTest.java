package org.trajeval.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ch.qos.logback.core.util.CachingDateFormatter;
import java.time.ZoneId;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@code %isotime} writes what logback's {@code %d{yyyy-MM-dd'T'HH:mm:ss.SSSXXX}} writes. Reference:
 * logback's own date formatter ({@link CachingDateFormatter}, what its {@code %d} converter calls).
 */
class LogTimeConverterTest {
    private static final String PATTERN = "yyyy-MM-dd'T'HH:mm:ss.SSSXXX";

    @Test
    void timesAreWrittenAsLogbacksDatePatternWritesThem() {
        // UTC, zones with half- and quarter-hour offsets, a 30-minute daylight saving shift, and ordinary DST zones;
        // times in order (as log lines come: many in one second), around DST changes, and seeded over 1900-2200
        Random rnd = new Random(20261126L);
        for (String id : new String[] {"UTC", "Europe/Berlin", "America/St_Johns", "Asia/Kathmandu",
            "Australia/Lord_Howe", "America/New_York", "Pacific/Chatham"}) {
            ZoneId zone = ZoneId.of(id);
            CachingDateFormatter reference = new CachingDateFormatter(PATTERN, zone, Locale.ROOT);
            LogTimeConverter converter = new LogTimeConverter(zone, Locale.ROOT);
            long t = 1_790_000_000_000L; // 2026-09-21
            for (int i = 0; i < 20_000; i++) {
                t += rnd.nextInt(3) == 0 ? rnd.nextInt(5_000) : rnd.nextInt(3);
                assertEquals(reference.format(t), converter.format(t), id + " at " + t);
            }
            for (int i = 0; i < 20_000; i++) {
                long at = -2_208_988_800_000L + (long) (rnd.nextDouble() * 9_467_280_000_000L);
                assertEquals(reference.format(at), converter.format(at), id + " at " + at);
            }
            // every millisecond of the hour around 2026's DST changes in Europe and North America
            for (long start : new long[] {1_774_746_000_000L, 1_792_890_000_000L, 1_772_953_200_000L}) {
                for (long at = start; at < start + 7_200_000L; at += 997) {
                    assertEquals(reference.format(at), converter.format(at), id + " at " + at);
                }
            }
        }
    }

    @Test
    void theTextLogPatternUsesIt() throws Exception {
        assertTrue(LogSetup.TEXT_PATTERN.startsWith("%isotime %-5level"), LogSetup.TEXT_PATTERN);
    }
}
