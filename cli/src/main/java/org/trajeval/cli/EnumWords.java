package org.trajeval.cli;

import java.util.Locale;
import picocli.CommandLine.TypeConversionException;

/** Command-line words to enum constants: case-insensitive, '-' for '_', a refusal naming the allowed words. */
final class EnumWords {
    private EnumWords() {
    }

    static <E extends Enum<E>> E parse(Class<E> type, String word, String allowed) {
        String key = word.trim().toUpperCase(Locale.ROOT).replace('-', '_');
        for (E e : type.getEnumConstants()) {
            if (e.name().equals(key)) {
                return e;
            }
        }
        throw new TypeConversionException("expected one of " + allowed + ", found \"" + word + "\"");
    }
}
