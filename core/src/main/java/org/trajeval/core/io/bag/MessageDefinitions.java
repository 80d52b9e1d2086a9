package org.trajeval.core.io.bag;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Parses ROS message definitions ({@code ros1msg} and {@code ros2msg}, as stored in bags: the main
 * definition, then each dependency after a line of {@code =} and {@code MSG: pkg/Type}) into a
 * {@link MessageType} tree. Lines are {@code TYPE NAME [DEFAULT]} fields or {@code TYPE NAME=VALUE}
 * constants (left out); {@code #} starts a comment. {@code Header} means {@code std_msgs/Header};
 * a bare type name is looked up in the package of the type that uses it. Types the text does not
 * define are taken from trajeval's copy of the standard definitions (rosbag2 sqlite3 files store
 * none), for the dialect the bag uses.
 */
final class MessageDefinitions {
    /** Largest fixed array length accepted in a definition. */
    static final int MAX_FIXED_LENGTH = 1 << 20;
    private static final Pattern SEPARATOR = Pattern.compile("^={3,}\\s*$");
    private static final Pattern MSG_LINE = Pattern.compile("^MSG:\\s*(\\S+)\\s*$");
    private static final Pattern IDENT = Pattern.compile("[A-Za-z][A-Za-z0-9_]*");
    private static final Pattern TYPE = Pattern.compile(
            "([A-Za-z][A-Za-z0-9_]*(?:/[A-Za-z][A-Za-z0-9_]*){0,2})(?:<=\\d+)?(?:\\[(<=)?(\\d*)\\])?");

    /** The bag's dialect: ROS 1 has {@code time}, {@code Header.seq}; ROS 2 has builtin_interfaces. */
    enum Dialect {
        ROS1, ROS2
    }

    private final String source;
    private final String topic;
    private final Dialect dialect;
    private final Map<String, List<String>> sections;
    private final Map<String, MessageType> built = new HashMap<>();
    private final Deque<String> building = new ArrayDeque<>();

    private MessageDefinitions(String source, String topic, Dialect dialect, Map<String, List<String>> sections) {
        this.source = source;
        this.topic = topic;
        this.dialect = dialect;
        this.sections = sections;
    }

    /**
     * @param typeName the main type, e.g. {@code nav_msgs/msg/Odometry}
     * @param text the definition text stored in the bag (empty: standard definitions only)
     * @return the parsed main type
     * @throws InputException (CORRUPT_BAG) naming the topic and line when the text does not parse
     */
    static MessageType parse(String source, String topic, String typeName, String text, Dialect dialect) {
        String main = normalise(typeName);
        Map<String, List<String>> sections = split(main, text);
        return new MessageDefinitions(source, topic, dialect, sections).type(main, null);
    }

    static String normalise(String name) {
        String n = name.strip();
        int a = n.indexOf('/');
        int b = n.lastIndexOf('/');
        if (a > 0 && b > a) {
            n = n.substring(0, a) + n.substring(b);
        }
        return n;
    }

    private static Map<String, List<String>> split(String main, String text) {
        Map<String, List<String>> sections = new LinkedHashMap<>();
        String current = main;
        List<String> lines = new ArrayList<>();
        boolean expectMsg = false;
        for (String raw : text.split("\r?\n", -1)) {
            if (SEPARATOR.matcher(raw).matches()) {
                sections.putIfAbsent(current, lines);
                lines = new ArrayList<>();
                current = null;
                expectMsg = true;
                continue;
            }
            if (expectMsg) {
                Matcher m = MSG_LINE.matcher(raw.strip());
                if (raw.isBlank()) {
                    continue;
                }
                if (m.matches()) {
                    current = normalise(m.group(1));
                    expectMsg = false;
                    continue;
                }
                current = "?";
                expectMsg = false;
            }
            lines.add(raw);
        }
        if (current != null) {
            sections.putIfAbsent(current, lines);
        }
        if (text.isBlank()) {
            sections.remove(main);
        }
        return sections;
    }

    private MessageType type(String name, String usedBy) {
        MessageType t = built.get(name);
        if (t != null) {
            return t;
        }
        if (building.contains(name)) {
            throw bad("type " + name + " contains itself", 0, null);
        }
        List<String> lines = sections.get(name);
        if (lines == null) {
            lines = standard(dialect).get(name);
        }
        if (lines == null) {
            throw bad("the definition text does not define type " + name
                    + (usedBy == null ? "" : " (used by " + usedBy + ")"), 0, null);
        }
        building.push(name);
        List<MessageType.Field> fields = new ArrayList<>();
        String pkg = name.contains("/") ? name.substring(0, name.indexOf('/')) : "";
        for (int i = 0; i < lines.size(); i++) {
            MessageType.Field f = field(name, pkg, lines.get(i), i + 1);
            if (f != null) {
                fields.add(f);
            }
        }
        building.pop();
        t = new MessageType(name, fields);
        built.put(name, t);
        return t;
    }

    private MessageType.Field field(String owner, String pkg, String raw, int lineNo) {
        String line = raw.strip();
        if (line.isEmpty() || line.startsWith("#")) {
            return null;
        }
        int sp = indexOfSpace(line);
        if (sp < 0) {
            throw bad("type " + owner + ", line " + lineNo + ": expected 'TYPE NAME'", lineNo, raw);
        }
        String typeText = line.substring(0, sp);
        String rest = line.substring(sp).strip();
        int eq = rest.indexOf('=');
        int hash = rest.indexOf('#');
        if (eq > 0 && (hash < 0 || eq < hash)) {
            return null; // a constant: TYPE NAME=VALUE
        }
        if (hash >= 0) {
            rest = rest.substring(0, hash).strip();
        }
        int sp2 = indexOfSpace(rest);
        String fieldName = sp2 < 0 ? rest : rest.substring(0, sp2);
        if (!IDENT.matcher(fieldName).matches()) {
            throw bad("type " + owner + ", line " + lineNo + ": '" + fieldName + "' is not a field name", lineNo, raw);
        }
        Matcher m = TYPE.matcher(typeText);
        if (!m.matches()) {
            throw bad("type " + owner + ", line " + lineNo + ": '" + typeText + "' is not a type", lineNo, raw);
        }
        String base = m.group(1);
        MessageType.Arity arity = MessageType.Arity.ONE;
        int length = 0;
        if (typeText.endsWith("]")) {
            String digits = m.group(3);
            if (m.group(2) != null || digits.isEmpty()) {
                arity = MessageType.Arity.SEQUENCE;
            } else {
                long n = digits.length() > 9 ? Long.MAX_VALUE : Long.parseLong(digits);
                if (n > MAX_FIXED_LENGTH) {
                    throw bad("type " + owner + ", line " + lineNo + ": array length " + digits + " exceeds "
                            + MAX_FIXED_LENGTH, lineNo, raw);
                }
                arity = MessageType.Arity.FIXED;
                length = (int) n;
            }
        }
        Primitive p = Primitive.named(base);
        if (p != null && (p == Primitive.TIME || p == Primitive.DURATION) && dialect == Dialect.ROS2) {
            p = null; // not primitives in ROS 2
        }
        if (p != null) {
            return new MessageType.Field(fieldName, p, null, arity, length);
        }
        String ref = resolve(base, pkg);
        return new MessageType.Field(fieldName, null, type(ref, owner), arity, length);
    }

    private String resolve(String base, String pkg) {
        if (base.equals("Header")) {
            return "std_msgs/Header";
        }
        if (base.contains("/")) {
            return normalise(base);
        }
        if (dialect == Dialect.ROS2 && (base.equals("time") || base.equals("duration"))) {
            return base.equals("time") ? "builtin_interfaces/Time" : "builtin_interfaces/Duration";
        }
        return pkg.isEmpty() ? base : pkg + "/" + base;
    }

    private static int indexOfSpace(String s) {
        for (int i = 0; i < s.length(); i++) {
            if (Character.isWhitespace(s.charAt(i))) {
                return i;
            }
        }
        return -1;
    }

    private InputException bad(String what, int line, String found) {
        return new InputException(source, 0, topic, InputProblem.CORRUPT_BAG, "the message definition of topic "
                + topic + " does not parse: " + what, found == null ? null : found.strip());
    }

    /** trajeval's copy of the standard definitions of the pose-bearing types (resources {@code ros1|ros2_standard.msg}). */
    private static Map<String, List<String>> standard(Dialect d) {
        return d == Dialect.ROS1 ? Standard.ROS1 : Standard.ROS2;
    }

    /** Loaded once, when first needed (class initialisation is thread-safe). */
    private static final class Standard {
        static final Map<String, List<String>> ROS1 = load("ros1_standard.msg");
        static final Map<String, List<String>> ROS2 = load("ros2_standard.msg");

        private static Map<String, List<String>> load(String name) {
            try (InputStream in = MessageDefinitions.class.getResourceAsStream(name)) {
                if (in == null) {
                    throw new IllegalStateException("resource " + name + " is missing from the build");
                }
                String text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
                Map<String, List<String>> all = split("?", "================\n" + text);
                all.remove("?");
                return Map.copyOf(all);
            } catch (IOException e) {
                throw new IllegalStateException("resource " + name + " cannot be read", e);
            }
        }
    }
}
