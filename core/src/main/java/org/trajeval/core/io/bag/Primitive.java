package org.trajeval.core.io.bag;

import java.util.Locale;

/** The primitive field types of ROS message definitions, with their serialised size (bytes). */
enum Primitive {
    BOOL(1), INT8(1), UINT8(1), INT16(2), UINT16(2), INT32(4), UINT32(4), INT64(8), UINT64(8), FLOAT32(4),
    FLOAT64(8),
    /** Length-prefixed text; size is the length prefix. */
    STRING(4),
    /** ROS 2 wstring: uint32 count of 2- or 4-byte units; read as bytes of 4. */
    WSTRING(4),
    /** ROS 1 {@code time}: uint32 secs, uint32 nsecs. */
    TIME(8),
    /** ROS 1 {@code duration}: int32 secs, int32 nsecs. */
    DURATION(8);

    final int size;

    Primitive(int size) {
        this.size = size;
    }

    /** @return the primitive named so in a definition (ROS 1 and ROS 2 spellings), or null for a message type */
    static Primitive named(String name) {
        return switch (name.toLowerCase(Locale.ROOT)) {
            case "bool" -> BOOL;
            case "int8", "byte" -> INT8;
            case "uint8", "char" -> UINT8;
            case "int16" -> INT16;
            case "uint16" -> UINT16;
            case "int32" -> INT32;
            case "uint32" -> UINT32;
            case "int64" -> INT64;
            case "uint64" -> UINT64;
            case "float32" -> FLOAT32;
            case "float64" -> FLOAT64;
            case "string" -> STRING;
            case "wstring" -> WSTRING;
            case "time" -> TIME;
            case "duration" -> DURATION;
            default -> null;
        };
    }

    /** @return CDR alignment (bytes): the size, 4 for the two-word ROS 1 times */
    int cdrAlignment() {
        return this == TIME || this == DURATION ? 4 : size;
    }
}
