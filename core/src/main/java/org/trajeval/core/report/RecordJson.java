package org.trajeval.core.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.util.DefaultPrettyPrinter;
import java.io.IOException;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.lang.annotation.Annotation;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Writes a report record as the pretty-printed JSON that {@link ReportJson}'s Jackson mapper
 * writes, through Jackson's streaming generator only: a cold process then skips the mapper's
 * set-up and its serializer introspection (about a fifth of a 10^4-pose {@code eval --json}).
 * The mapping stays in the records' annotations; this class reads them by reflection and follows
 * the part of Jackson's rules the report records use:
 * <ul>
 * <li>properties: the record components and public instance methods annotated
 *     {@code @JsonProperty("name")}, in the order of the class's {@code @JsonPropertyOrder},
 *     which must list every one of them;</li>
 * <li>{@code @JsonInclude(NON_NULL)} on the class leaves out null values, otherwise null is
 *     written as null;</li>
 * <li>{@code double} and {@code Double}: a number, or null when not finite (ReportJson's rule);
 *     {@code double[]} elements as Jackson's array serializer writes them;</li>
 * <li>values: String, int, long, boolean (and their boxes), double[], double[][], a List of
 *     supported values, a Map of String keys to supported values (an object, entries in the map's
 *     order, null values written as null), a supported record.</li>
 * </ul>
 * Any other type, annotation or an auto-detected getter makes {@link #supports} false, and
 * ReportJson uses the mapper. {@code RecordJsonTest} checks the output against the mapper's.
 */
final class RecordJson {
    private static final JsonFactory FACTORY = new JsonFactory();

    /** Whether a type is written here: derived from the class alone, so computed once per class. */
    private static final ClassValue<Boolean> SUPPORTED = new ClassValue<>() {
        @Override
        protected Boolean computeValue(Class<?> type) {
            return supportsRecord(type, new ArrayList<>());
        }
    };

    /** The properties of a supported record type in writing order, computed once per class. */
    private static final ClassValue<Layout> LAYOUTS = new ClassValue<>() {
        @Override
        protected Layout computeValue(Class<?> type) {
            return Layout.of(type);
        }
    };

    private RecordJson() {
    }

    /** A supported record type's JSON object: its property names and getters in order, and its null rule. */
    private record Layout(boolean leaveOutNulls, String[] names, Method[] getters) {
        static Layout of(Class<?> type) {
            Map<String, Method> getters = new LinkedHashMap<>();
            for (RecordComponent c : type.getRecordComponents()) {
                getters.put(c.getAccessor().getAnnotation(JsonProperty.class).value(), c.getAccessor());
            }
            for (Method m : type.getMethods()) {
                JsonProperty p = m.getAnnotation(JsonProperty.class);
                if (p != null && m.getParameterCount() == 0 && !Modifier.isStatic(m.getModifiers())) {
                    getters.putIfAbsent(p.value(), m);
                }
            }
            String[] names = type.getAnnotation(JsonPropertyOrder.class).value();
            Method[] ordered = new Method[names.length];
            for (int i = 0; i < names.length; i++) {
                ordered[i] = getters.get(names[i]);
            }
            JsonInclude include = type.getAnnotation(JsonInclude.class);
            return new Layout(include != null && include.value() == JsonInclude.Include.NON_NULL, names, ordered);
        }
    }

    /** @return whether {@link #write} writes {@code type} and every type it holds exactly like the mapper */
    static boolean supports(Class<?> type) {
        return SUPPORTED.get(type);
    }

    /** @return {@code report} (a record type {@link #supports}) as pretty-printed JSON */
    static String write(Object report) {
        StringWriter out = new StringWriter(4096);
        try (JsonGenerator g = FACTORY.createGenerator(out)) {
            g.setPrettyPrinter(new DefaultPrettyPrinter());
            writeRecord(g, report);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return out.toString();
    }

    private static boolean supportsRecord(Class<?> type, List<Class<?>> seen) {
        if (seen.contains(type)) {
            return true;
        }
        seen.add(type);
        if (!type.isRecord() || !Modifier.isPublic(type.getModifiers())
                || type.getEnclosingClass() != null && !Modifier.isPublic(type.getEnclosingClass().getModifiers())) {
            return false;
        }
        for (Annotation a : type.getAnnotations()) {
            if (!(a instanceof JsonPropertyOrder) && !(a instanceof JsonInclude && isNonNullOrAlways((JsonInclude) a))) {
                return false;
            }
        }
        Map<String, Type> props = new LinkedHashMap<>();
        for (RecordComponent c : type.getRecordComponents()) {
            // @JsonProperty (targets field, method, parameter) reaches the accessor, not the component
            JsonProperty p = c.getAccessor().getAnnotation(JsonProperty.class);
            if (!onlyJsonProperty(c.getAnnotations()) || !onlyJsonProperty(c.getAccessor().getAnnotations())
                    || p == null || props.put(p.value(), c.getGenericType()) != null) {
                return false;
            }
        }
        for (Method m : type.getMethods()) {
            if (Modifier.isStatic(m.getModifiers()) || m.getParameterCount() != 0 || isComponentAccessor(type, m)) {
                continue;
            }
            JsonProperty p = m.getAnnotation(JsonProperty.class);
            if (p == null) {
                if (looksLikeGetter(m) || m.getAnnotations().length > 0) {
                    return false; // Jackson would write it (or treat it specially)
                }
            } else if (!onlyJsonProperty(m.getAnnotations()) || props.put(p.value(), m.getGenericReturnType()) != null) {
                return false;
            }
        }
        JsonPropertyOrder order = type.getAnnotation(JsonPropertyOrder.class);
        if (order == null || order.alphabetic() || !List.of(order.value()).containsAll(props.keySet())
                || order.value().length != props.size()) {
            return false;
        }
        for (Type t : props.values()) {
            if (!supportsValue(t, seen)) {
                return false;
            }
        }
        return true;
    }

    private static boolean supportsValue(Type t, List<Class<?>> seen) {
        if (t instanceof ParameterizedType p) {
            Type[] args = p.getActualTypeArguments();
            return p.getRawType() == List.class && supportsValue(args[0], seen)
                    || p.getRawType() == Map.class && args[0] == String.class && supportsValue(args[1], seen);
        }
        if (!(t instanceof Class<?> c)) {
            return false;
        }
        return c == String.class || c == int.class || c == Integer.class || c == long.class || c == Long.class
                || c == boolean.class || c == Boolean.class || c == double.class || c == Double.class
                || c == double[].class || c == double[][].class || supportsRecord(c, seen);
    }

    private static boolean isNonNullOrAlways(JsonInclude a) {
        return (a.value() == JsonInclude.Include.NON_NULL || a.value() == JsonInclude.Include.ALWAYS)
                && a.content() == JsonInclude.Include.ALWAYS;
    }

    private static boolean onlyJsonProperty(Annotation[] annotations) {
        for (Annotation a : annotations) {
            if (!(a instanceof JsonProperty p) || p.access() != JsonProperty.Access.AUTO) {
                return false;
            }
        }
        return true;
    }

    private static boolean isComponentAccessor(Class<?> type, Method m) {
        for (RecordComponent c : type.getRecordComponents()) {
            if (c.getName().equals(m.getName())) {
                return true;
            }
        }
        return m.getDeclaringClass() == Object.class || m.getDeclaringClass() == Record.class;
    }

    private static boolean looksLikeGetter(Method m) {
        String n = m.getName();
        return n.startsWith("get") && n.length() > 3
                || n.startsWith("is") && n.length() > 2 && (m.getReturnType() == boolean.class
                        || m.getReturnType() == Boolean.class);
    }

    private static void writeRecord(JsonGenerator g, Object record) throws IOException {
        Layout layout = LAYOUTS.get(record.getClass());
        g.writeStartObject(record);
        for (int i = 0; i < layout.names().length; i++) {
            Object v = get(layout.getters()[i], record);
            if (v == null && layout.leaveOutNulls()) {
                continue;
            }
            g.writeFieldName(layout.names()[i]);
            writeValue(g, v);
        }
        g.writeEndObject();
    }

    private static Object get(Method m, Object record) {
        try {
            return m.invoke(record);
        } catch (IllegalAccessException | InvocationTargetException e) {
            throw new IllegalStateException("report property " + m.getName() + " could not be read", e);
        }
    }

    private static void writeValue(JsonGenerator g, Object v) throws IOException {
        if (v == null) {
            g.writeNull();
        } else if (v instanceof String s) {
            g.writeString(s);
        } else if (v instanceof Double d) {
            if (Double.isFinite(d)) {
                g.writeNumber(d.doubleValue());
            } else {
                g.writeNull();
            }
        } else if (v instanceof Integer i) {
            g.writeNumber(i.intValue());
        } else if (v instanceof Long l) {
            g.writeNumber(l.longValue());
        } else if (v instanceof Boolean b) {
            g.writeBoolean(b);
        } else if (v instanceof double[] a) {
            g.writeArray(a, 0, a.length);
        } else if (v instanceof double[][] rows) {
            g.writeStartArray(rows, rows.length);
            for (double[] row : rows) {
                writeValue(g, row);
            }
            g.writeEndArray();
        } else if (v instanceof Map<?, ?> map) {
            g.writeStartObject(map);
            for (Map.Entry<?, ?> e : map.entrySet()) {
                g.writeFieldName((String) e.getKey());
                writeValue(g, e.getValue());
            }
            g.writeEndObject();
        } else if (v instanceof List<?> list) {
            g.writeStartArray(list, list.size());
            for (Object e : list) {
                writeValue(g, e);
            }
            g.writeEndArray();
        } else {
            writeRecord(g, v);
        }
    }
}
