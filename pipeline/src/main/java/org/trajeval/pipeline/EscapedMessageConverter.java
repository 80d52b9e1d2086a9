package org.trajeval.pipeline;

import ch.qos.logback.classic.pattern.ClassicConverter;
import ch.qos.logback.classic.spi.ILoggingEvent;
import org.trajeval.core.InputText;

/**
 * Logback's {@code %emsg}: the formatted message with control characters escaped
 * ({@link InputText#escape}), so a bundle or file name holding a newline or a terminal escape
 * cannot split a text log line or forge one. The JSON log format escapes by itself.
 */
public final class EscapedMessageConverter extends ClassicConverter {
    @Override
    public String convert(ILoggingEvent event) {
        return InputText.escape(event.getFormattedMessage());
    }
}
