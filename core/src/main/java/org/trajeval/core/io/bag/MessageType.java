package org.trajeval.core.io.bag;

import java.util.List;
import java.util.Objects;

/**
 * A message type parsed from its definition text: the fields in serialisation order.
 *
 * @param name normalised type name, {@code package/Type} (ROS 2's {@code /msg/} removed)
 * @param fields the fields (constants left out)
 */
record MessageType(String name, List<Field> fields) {
    /** How many values a field holds. */
    enum Arity {
        /** One value. */
        ONE,
        /** {@code T[N]}: exactly N values, no count on the wire. */
        FIXED,
        /** {@code T[]} or {@code T[<=N]}: a uint32 count, then the values. */
        SEQUENCE
    }

    /**
     * One field.
     *
     * @param name field name
     * @param primitive the primitive type, or null for a nested message
     * @param nested the nested message type, or null for a primitive
     * @param arity one value, a fixed array or a sequence
     * @param length the fixed array length (0 unless FIXED)
     */
    record Field(String name, Primitive primitive, MessageType nested, Arity arity, int length) {
        Field {
            Objects.requireNonNull(name, "name");
            if ((primitive == null) == (nested == null)) {
                throw new IllegalArgumentException("a field is either primitive or nested: " + name);
            }
        }
    }

    MessageType {
        Objects.requireNonNull(name, "name");
        fields = List.copyOf(fields);
    }

    /** @return the field of that name, or null */
    Field field(String fieldName) {
        for (Field f : fields) {
            if (f.name().equals(fieldName)) {
                return f;
            }
        }
        return null;
    }
}
