package org.trajeval.pipeline;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.LoggerContext;
import ch.qos.logback.classic.encoder.PatternLayoutEncoder;
import ch.qos.logback.classic.spi.Configurator;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.ConsoleAppender;
import ch.qos.logback.core.CoreConstants;
import ch.qos.logback.core.pattern.DynamicConverter;
import ch.qos.logback.core.spi.ContextAwareBase;
import java.util.HashMap;
import java.util.Map;
import java.util.function.Supplier;
import org.slf4j.Logger;

/**
 * The service's logging, set up in code (logback's {@link Configurator} service, listed in
 * {@code META-INF/services}) instead of parsed from a {@code logback.xml} at every start (issue 15:
 * about 0.1-0.18 s of the start). Text lines on stderr: {@value #TEXT_PATTERN}; the option
 * {@code log-format json} then switches the root to JSON lines ({@link LogFormat#apply}). The Kafka
 * clients retry on their own and log every retry as WARN (several lines a second while a broker is
 * away): their loggers are quieted and trajeval logs one line per change of state ({@code BrokerWatch}).
 * <p>
 * A user's logback configuration wins, as logback's own order has it: the system property
 * {@code logback.configurationFile}, or a {@code logback-test.xml} or {@code logback.xml} on the class
 * path; then this class steps aside and logback reads that file.
 */
public final class LogSetup extends ContextAwareBase implements Configurator {
    /** The text lines: time (ISO-8601, the JVM's zone), level, thread, logger, escaped message. */
    public static final String TEXT_PATTERN = "%isotime %-5level [%thread] %logger{24} - %emsg%n";

    /** Loggers given their own level: the Kafka clients' retries and the broker fixture's state changes. */
    static final Map<String, Level> LEVELS = Map.of("org.apache.kafka", Level.ERROR, "kafka", Level.WARN,
            "state.change.logger", Level.WARN);

    @Override
    public ExecutionStatus configure(LoggerContext ctx) {
        if (userConfiguration(getClass().getClassLoader())) {
            return ExecutionStatus.INVOKE_NEXT_IF_ANY;
        }
        apply(ctx);
        return ExecutionStatus.DO_NOT_INVOKE_NEXT_IF_ANY;
    }

    /** Sets up {@code ctx} with the service's appender, pattern and levels. */
    static void apply(LoggerContext ctx) {
        // %emsg: the message with control characters escaped (a name with a newline cannot forge a line);
        // %isotime: %d{yyyy-MM-dd'T'HH:mm:ss.SSSXXX}'s text, formatted once per second (LogTimeConverter)
        Map<String, Supplier<DynamicConverter<?>>> rules = new HashMap<>();
        rules.put("emsg", EscapedMessageConverter::new);
        rules.put("isotime", LogTimeConverter::new);
        ctx.putObject(CoreConstants.PATTERN_RULE_REGISTRY_FOR_SUPPLIERS, rules);
        PatternLayoutEncoder encoder = new PatternLayoutEncoder();
        encoder.setContext(ctx);
        encoder.setPattern(TEXT_PATTERN);
        encoder.start();
        ConsoleAppender<ILoggingEvent> appender = new ConsoleAppender<>();
        appender.setContext(ctx);
        appender.setName("STDERR");
        appender.setTarget("System.err");
        appender.setEncoder(encoder);
        appender.start();
        LEVELS.forEach((name, level) -> ctx.getLogger(name).setLevel(level));
        ch.qos.logback.classic.Logger root = ctx.getLogger(Logger.ROOT_LOGGER_NAME);
        root.setLevel(Level.INFO);
        root.addAppender(appender);
    }

    /** @return whether logback would find a configuration of the user's: the property or a file on the class path */
    static boolean userConfiguration(ClassLoader loader) {
        return System.getProperty("logback.configurationFile") != null
                || loader.getResource("logback-test.xml") != null || loader.getResource("logback.xml") != null;
    }
}
