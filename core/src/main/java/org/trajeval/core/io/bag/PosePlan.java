package org.trajeval.core.io.bag;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * A message type compiled once into a field plan that pulls the stamp, the pose and the frame names
 * out of serialised messages with no per-message reflection or allocation: fields on the wanted
 * paths are read into slots, every other field is skipped by its type.
 *
 * <p>Two wire formats: CDR (ROS 2; 4-byte encapsulation header, little- or big-endian, every
 * primitive aligned to its size relative to the end of that header, strings with their NUL) and
 * ROS 1 serialisation (little-endian, no alignment, strings without NUL, {@code time} = uint32
 * secs + uint32 nsecs). Sequences and strings carry a uint32 count; fixed arrays none.
 */
final class PosePlan {
    /** Numeric slots: position (m), orientation quaternion, stamp seconds and nanoseconds. */
    static final int X = 0, Y = 1, Z = 2, QX = 3, QY = 4, QZ = 5, QW = 6, SEC = 7, NSEC = 8, SLOTS = 9;
    /** String slots: the header's frame_id, the child_frame_id. */
    static final int FRAME = 0, CHILD = 1;

    /** Receives one pose: the numeric and string slots (valid only during the call). */
    interface Emit {
        void pose(double[] v, String[] s);
    }

    private static final VarHandle LE64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle BE64 = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle LE32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.LITTLE_ENDIAN);
    private static final VarHandle BE32 = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);

    private static final int SKIP = 0, NUMBER = 1, TIME = 2, STRING = 3, DESCEND = 4, REPEAT = 5;

    /** One step of the plan: what to do with one field. */
    private record Op(int kind, MessageType.Field field, int slot, Op[] children) {
    }

    private final Op[] root;
    private final boolean repeat;
    private final boolean cdr;
    private final double[] v = new double[SLOTS];
    private final String[] s = new String[2];
    // decoding state
    private byte[] buf;
    private int pos;
    private int end;
    private int origin;
    private boolean little;

    private PosePlan(Op[] root, boolean repeat, boolean cdr) {
        this.root = root;
        this.repeat = repeat;
        this.cdr = cdr;
    }

    /**
     * @param type the message type
     * @param captures field path ("header.stamp.sec") to slot: numeric slots as is, string slots as
     *     {@code -1 - slot}; a ROS 1 {@code time} field maps to {@link #SEC}
     * @param repeatPath the sequence field whose elements each give one pose (paths in
     *     {@code captures} are then relative to the element), or null
     * @param cdr CDR (ROS 2) or ROS 1 serialisation
     */
    static PosePlan compile(MessageType type, Map<String, Integer> captures, String repeatPath, boolean cdr) {
        Op[] ops = ops(type, "", captures, repeatPath);
        return new PosePlan(ops, repeatPath != null, cdr);
    }

    private static Op[] ops(MessageType type, String prefix, Map<String, Integer> captures, String repeatPath) {
        List<Op> out = new ArrayList<>();
        for (MessageType.Field f : type.fields()) {
            String path = prefix + f.name();
            Integer slot = captures.get(path);
            boolean one = f.arity() == MessageType.Arity.ONE;
            if (repeatPath != null && path.equals(repeatPath) && f.nested() != null
                    && f.arity() == MessageType.Arity.SEQUENCE) {
                out.add(new Op(REPEAT, f, 0, ops(f.nested(), "", captures, null)));
            } else if (slot != null && one && f.primitive() == Primitive.TIME) {
                out.add(new Op(TIME, f, SEC, null));
            } else if (slot != null && one && f.primitive() == Primitive.STRING && slot < 0) {
                out.add(new Op(STRING, f, -1 - slot, null));
            } else if (slot != null && one && f.primitive() != null && slot >= 0 && f.primitive() != Primitive.STRING
                    && f.primitive() != Primitive.WSTRING && f.primitive() != Primitive.DURATION) {
                out.add(new Op(NUMBER, f, slot, null));
            } else if (one && f.nested() != null && hasPrefix(captures, path + ".", repeatPath)) {
                out.add(new Op(DESCEND, f, 0, ops(f.nested(), path + ".", captures, repeatPath)));
            } else {
                out.add(new Op(SKIP, f, 0, null));
            }
        }
        return out.toArray(new Op[0]);
    }

    private static boolean hasPrefix(Map<String, Integer> captures, String prefix, String repeatPath) {
        if (repeatPath != null && repeatPath.startsWith(prefix)) {
            return true;
        }
        for (String k : captures.keySet()) {
            if (k.startsWith(prefix)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Decodes one message and emits its pose (or one pose per element of the repeated field).
     *
     * @throws DecodeException when the bytes end before the plan does, or a count cannot fit
     */
    void decode(byte[] data, int offset, int length, Emit emit) {
        this.buf = data;
        this.pos = offset;
        this.end = offset + length;
        if (cdr) {
            if (length < 4) {
                throw new DecodeException("the message has " + length + " bytes, fewer than the 4-byte CDR header");
            }
            int kind = data[offset + 1] & 0xff;
            if (data[offset] != 0 || (kind != 0 && kind != 1)) {
                throw new DecodeException("the CDR encapsulation header is " + String.format("%02x %02x",
                        data[offset] & 0xff, data[offset + 1] & 0xff) + ", expected 00 01 (CDR little-endian) or 00 00");
            }
            little = kind == 1;
            pos = offset + 4;
            origin = pos;
        } else {
            little = true;
            origin = offset;
        }
        java.util.Arrays.fill(v, 0.0);
        s[0] = null;
        s[1] = null;
        run(root, emit);
        if (!repeat) {
            emit.pose(v, s);
        }
    }

    private void run(Op[] ops, Emit emit) {
        for (Op op : ops) {
            switch (op.kind) {
                case NUMBER -> v[op.slot] = number(op.field.primitive());
                case TIME -> {
                    align(4);
                    need(8);
                    v[SEC] = u32();
                    v[NSEC] = u32();
                }
                case STRING -> s[op.slot] = string();
                case DESCEND -> run(op.children, emit);
                case REPEAT -> {
                    long n = count(1);
                    for (long i = 0; i < n; i++) {
                        run(op.children, emit);
                        emit.pose(v, s);
                    }
                }
                default -> skip(op.field);
            }
        }
    }

    // Each VarHandle.get is cast where it is called: inside a ?: without its own cast the call is
    // typed Object, which boxes every value and takes the generic (slow) invocation path.
    private double number(Primitive p) {
        align(p.cdrAlignment());
        need(p.size);
        int at = pos;
        pos += p.size;
        return switch (p) {
            case FLOAT64 -> Double.longBitsToDouble((little ? (long) LE64.get(buf, at) : (long) BE64.get(buf, at)));
            case FLOAT32 -> Float.intBitsToFloat((little ? (int) LE32.get(buf, at) : (int) BE32.get(buf, at)));
            case INT32 -> (little ? (int) LE32.get(buf, at) : (int) BE32.get(buf, at));
            case UINT32 -> ((little ? (int) LE32.get(buf, at) : (int) BE32.get(buf, at))) & 0xffffffffL;
            case INT64 -> (little ? (long) LE64.get(buf, at) : (long) BE64.get(buf, at));
            case UINT64 -> unsigned((little ? (long) LE64.get(buf, at) : (long) BE64.get(buf, at)));
            case INT16 -> (short) (little ? (buf[at] & 0xff | buf[at + 1] << 8) : (buf[at + 1] & 0xff | buf[at] << 8));
            case UINT16 -> little ? (buf[at] & 0xff | (buf[at + 1] & 0xff) << 8) : (buf[at + 1] & 0xff | (buf[at] & 0xff) << 8);
            case INT8 -> buf[at];
            default -> buf[at] & 0xff;
        };
    }

    private static double unsigned(long x) {
        return x >= 0 ? x : (double) (x >>> 1) * 2.0 + (x & 1);
    }

    private long u32() {
        int at = pos;
        pos += 4;
        return ((little ? (int) LE32.get(buf, at) : (int) BE32.get(buf, at))) & 0xffffffffL;
    }

    /** A uint32 count of elements of at least {@code minBytes} each, checked against what remains. */
    private long count(int minBytes) {
        align(4);
        need(4);
        long n = u32();
        if (n * Math.max(1, minBytes) > end - pos) {
            throw new DecodeException("a count of " + n + " elements needs more than the " + (end - pos)
                    + " bytes left in the message");
        }
        return n;
    }

    private String string() {
        long n = count(1);
        int len = (int) n;
        int text = cdr && len > 0 ? len - 1 : len; // CDR strings end with a NUL counted in the length
        String out = new String(buf, pos, text, java.nio.charset.StandardCharsets.UTF_8);
        pos += len;
        return out;
    }

    private void skip(MessageType.Field f) {
        switch (f.arity()) {
            case ONE -> skipValue(f);
            case FIXED -> skipMany(f, f.length());
            default -> skipMany(f, count(f.primitive() != null ? f.primitive().size : 1));
        }
    }

    private void skipMany(MessageType.Field f, long n) {
        Primitive p = f.primitive();
        if (p != null && p != Primitive.STRING && p != Primitive.WSTRING) {
            if (n == 0) {
                return;
            }
            align(p.cdrAlignment());
            long bytes = n * p.size;
            if (bytes > end - pos) {
                throw new DecodeException("field " + f.name() + " needs " + bytes + " bytes, " + (end - pos) + " are left");
            }
            pos += (int) bytes;
            return;
        }
        for (long i = 0; i < n; i++) {
            skipValue(f);
        }
    }

    private void skipValue(MessageType.Field f) {
        Primitive p = f.primitive();
        if (p == null) {
            for (MessageType.Field g : f.nested().fields()) {
                skip(g);
            }
        } else if (p == Primitive.STRING) {
            long n = count(1);
            pos += (int) n;
        } else if (p == Primitive.WSTRING) {
            long n = count(4);
            pos += (int) (n * 4);
        } else {
            align(p.cdrAlignment());
            need(p.size);
            pos += p.size;
        }
    }

    private void align(int n) {
        if (cdr && n > 1) {
            int rel = pos - origin;
            int pad = (n - (rel & (n - 1))) & (n - 1);
            need(pad);
            pos += pad;
        }
    }

    private void need(int n) {
        if (n > end - pos) {
            throw new DecodeException("the message ends " + (n - (end - pos)) + " bytes too early");
        }
    }

    /** A message whose bytes do not fit its type; the caller adds topic and message number. */
    static final class DecodeException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        DecodeException(String message) {
            super(message, null, false, false);
        }
    }
}
