package org.trajeval.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.LoggerContext;
import ch.qos.logback.classic.joran.JoranConfigurator;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.classic.spi.LoggingEvent;
import ch.qos.logback.core.OutputStreamAppender;
import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.slf4j.Logger;

/**
 * The service's logging set up in code ({@link LogSetup}) writes what session 9's {@code logback.xml}
 * wrote (that file, kept as the test resource {@code logback-session9.xml}, read by logback's own
 * Joran configurator is the reference), and a user's logback configuration still wins.
 */
class LogSetupTest {
    @TempDir
    Path dir;

    private static LoggerContext fromXml() throws Exception {
        LoggerContext ctx = new LoggerContext();
        JoranConfigurator joran = new JoranConfigurator();
        joran.setContext(ctx);
        joran.doConfigure(LogSetupTest.class.getResource("logback-session9.xml"));
        return ctx;
    }

    private static LoggerContext inCode() {
        LoggerContext ctx = new LoggerContext();
        LogSetup.apply(ctx);
        return ctx;
    }

    @SuppressWarnings("unchecked")
    private static String line(LoggerContext ctx, ILoggingEvent e) {
        OutputStreamAppender<ILoggingEvent> a = (OutputStreamAppender<ILoggingEvent>) ctx.getLogger(Logger.ROOT_LOGGER_NAME)
                .getAppender("STDERR");
        return new String(a.getEncoder().encode(e), StandardCharsets.UTF_8);
    }

    private static LoggingEvent event(String logger, Level level, String thread, long millis, String message, Object... args) {
        LoggingEvent e = new LoggingEvent();
        e.setLoggerName(logger);
        e.setLevel(level);
        e.setThreadName(thread);
        e.setTimeStamp(millis);
        e.setMessage(message);
        e.setArgumentArray(args);
        return e;
    }

    @Test
    void textLinesAreTheBytesSessionNinesLogbackXmlWrote() throws Exception {
        LoggerContext xml = fromXml();
        LoggerContext code = inCode();
        List<LoggingEvent> events = new ArrayList<>();
        events.add(event("org.trajeval.pipeline.dir.DirectoryService", Level.WARN, "trajeval-commit", 1_795_000_000_123L,
                "failed bundle={} stage={}", "evil\n2026-11-23T00:00:00Z INFO forged \u001b]0;PWNED\u0007", "unpack"));
        events.add(event("org.trajeval.pipeline.dir.DirectoryService", Level.INFO, "main", 1_795_000_000_999L,
                "reported run_id={} version={}", "run-1", 1));
        events.add(event("a.very.long.logger.name.that.gets.abbreviated.Here", Level.ERROR, "w", 1_795_000_001_000L, "x"));
        events.add(event("Short", Level.DEBUG, "thread with spaces", 0L, "{} {}", null, "ü"));
        for (LoggingEvent e : events) {
            assertEquals(line(xml, e), line(code, e), e.getMessage());
        }
        String first = line(code, events.get(0));
        assertEquals(first.substring(first.indexOf(' ')), " WARN  [trajeval-commit] o.t.p.d.DirectoryService - failed "
                + "bundle=evil\\n2026-11-23T00:00:00Z INFO forged \\e]0;PWNED\\a stage=unpack" + System.lineSeparator(),
                "time, level, thread, abbreviated logger, escaped message");
    }

    @Test
    void everyLoggerHasTheLevelSessionNinesLogbackXmlGaveIt() throws Exception {
        LoggerContext xml = fromXml();
        LoggerContext code = inCode();
        for (String name : List.of(Logger.ROOT_LOGGER_NAME, "org.apache.kafka", "org.apache.kafka.clients.NetworkClient", "kafka",
                "kafka.server", "state.change.logger", "org.trajeval.pipeline.dir.DirectoryService", "org.apache", "other")) {
            assertEquals(xml.getLogger(name).getEffectiveLevel(), code.getLogger(name).getEffectiveLevel(), name);
        }
        assertEquals(1, count(code), "one appender, on the root");
        assertEquals(count(xml), count(code));
    }

    private static int count(LoggerContext ctx) {
        int n = 0;
        for (var it = ctx.getLogger(Logger.ROOT_LOGGER_NAME).iteratorForAppenders(); it.hasNext(); it.next()) {
            n++;
        }
        return n;
    }

    @Test
    void aLogbackXmlOrLogbackTestXmlOnTheClassPathMakesItStepAside() throws IOException {
        try (URLClassLoader none = new URLClassLoader(new URL[] {dir.toUri().toURL()}, null)) {
            assertFalse(LogSetup.userConfiguration(none), "nothing of the user's: the service's logging");
        }
        for (String name : List.of("logback.xml", "logback-test.xml")) {
            Path d = Files.createDirectories(dir.resolve(name + ".d"));
            Files.writeString(d.resolve(name), "<configuration/>");
            try (URLClassLoader user = new URLClassLoader(new URL[] {d.toUri().toURL()}, null)) {
                assertTrue(LogSetup.userConfiguration(user), name);
            }
        }
    }

    /** Runs {@code watch --drain} on a root with one unreadable bundle in a child JVM: @return its stderr */
    private String drainOneFailure(String classpath, String... jvmArgs) throws Exception {
        Path root = Files.createTempDirectory(dir, "root");
        Files.createDirectories(root.resolve("incoming/bad"));
        Files.createFile(root.resolve("incoming/bad.done"));
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx128m", "-XX:TieredStopAtLevel=1"));
        cmd.addAll(List.of(jvmArgs));
        cmd.addAll(List.of("-cp", classpath, PipelineCommand.class.getName(), "watch", "--root", root.toString(), "--drain"));
        Path err = root.resolve("stderr");
        Process p = new ProcessBuilder(cmd).redirectError(err.toFile()).redirectOutput(root.resolve("stdout").toFile()).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(PipelineCommand.SOME_FAILED, p.exitValue(), () -> read(err));
        return read(err);
    }

    private static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    void theServiceLogsItsOwnLinesUnlessTheUserNamesAConfigurationFileOrPutsALogbackXmlOnTheClassPath() throws Exception {
        String launcher = LauncherClasspath.withoutTestLogging();
        String own = drainOneFailure(launcher);
        assertTrue(own.matches("(?s)\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\d\\.\\d{3}\\S+ WARN  \\[trajeval-commit\\] "
                + "o\\.t\\.p\\.d\\.DirectoryService - failed bundle=bad stage=manifest .*"), own);

        Path custom = dir.resolve("custom.xml");
        Files.writeString(custom, "<configuration><appender name=\"E\" class=\"ch.qos.logback.core.ConsoleAppender\">"
                + "<target>System.err</target><encoder><pattern>CUSTOM %level %msg%n</pattern></encoder></appender>"
                + "<root level=\"INFO\"><appender-ref ref=\"E\"/></root></configuration>");
        String byProperty = drainOneFailure(launcher, "-Dlogback.configurationFile=" + custom);
        assertTrue(byProperty.startsWith("CUSTOM WARN failed bundle=bad stage=manifest"), byProperty);

        Path onPath = Files.createDirectories(dir.resolve("user-cp"));
        Files.copy(custom, onPath.resolve("logback.xml"));
        String byClassPath = drainOneFailure(onPath + java.io.File.pathSeparator + launcher);
        assertTrue(byClassPath.startsWith("CUSTOM WARN failed bundle=bad stage=manifest"), byClassPath);
    }
}
