package org.trajeval.api;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.Version;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/**
 * Keeps the public API (listed in org.trajeval.api's package-info.java and the README) closed: the
 * public members of its types mention only its own types and the JDK's, never an internal
 * trajeval type or a library's (Jackson, EJML, Commons).
 */
class PublicApiSurfaceTest {
    /** The public API, as package-info.java of org.trajeval.api states it. */
    private static final List<Class<?>> API = List.of(TrajectoryEvaluator.class, Poses.class, Version.class,
            InputException.class, InputProblem.class, EvaluationReport.class, ReportJson.class);

    /** Public members of API types that are internal, each saying so in its Javadoc. */
    private static final Set<String> INTERNAL_MEMBERS = Set.of(
            // the evaluator's bridge from core's statistics to the report
            "org.trajeval.core.report.EvaluationReport$Stats.of");

    @Test
    void publicMembersOfTheApiMentionOnlyApiAndJdkTypes() {
        Set<Class<?>> allowed = new LinkedHashSet<>(API);
        for (Class<?> c : API) {
            allowed.addAll(List.of(c.getDeclaredClasses()));
        }
        List<String> leaks = new ArrayList<>();
        for (Class<?> c : allowed) {
            if (!Modifier.isPublic(c.getModifiers())) {
                continue;
            }
            for (Method m : c.getDeclaredMethods()) {
                if (Modifier.isPublic(m.getModifiers()) && !m.isSynthetic()) {
                    check(c.getName() + "." + m.getName(), m.getReturnType(), allowed, leaks);
                    for (Class<?> p : m.getParameterTypes()) {
                        check(c.getName() + "." + m.getName(), p, allowed, leaks);
                    }
                }
            }
            for (Constructor<?> k : c.getDeclaredConstructors()) {
                if (Modifier.isPublic(k.getModifiers())) {
                    for (Class<?> p : k.getParameterTypes()) {
                        check(c.getName() + ".<init>", p, allowed, leaks);
                    }
                }
            }
            for (Field f : c.getDeclaredFields()) {
                if (Modifier.isPublic(f.getModifiers())) {
                    check(c.getName() + "." + f.getName(), f.getType(), allowed, leaks);
                }
            }
        }
        assertEquals(List.of(), leaks, "public API signatures mention non-API types");
    }

    private static void check(String where, Class<?> type, Set<Class<?>> allowed, List<String> leaks) {
        Class<?> t = type;
        while (t.isArray()) {
            t = t.getComponentType();
        }
        if (t.isPrimitive() || t.getName().startsWith("java.") || allowed.contains(t) || INTERNAL_MEMBERS.contains(where)) {
            return;
        }
        leaks.add(where + ": " + t.getName());
    }
}
