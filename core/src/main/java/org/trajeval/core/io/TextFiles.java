package org.trajeval.core.io;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Reads a whole text document (manifest, configuration, report) as strict UTF-8. Bytes that are
 * not UTF-8 are refused with {@link InputProblem#NOT_UTF8}, naming the line and byte offset and,
 * when a byte-order mark or NUL bytes show it, that the file is UTF-16. Reads the file once, as a
 * stream, so a pipe works too. A leading UTF-8 byte-order mark is dropped.
 */
public final class TextFiles {
    private TextFiles() {
    }

    /**
     * @param file the document
     * @param what how to name it in messages, e.g. "manifest"
     * @param maxBytes largest accepted size (bytes)
     * @return its text
     * @throws InputException when it is missing, unreadable, too large or not UTF-8
     */
    public static String readUtf8(Path file, String what, long maxBytes) {
        String source = file.toString();
        byte[] bytes;
        try (var in = Files.newInputStream(file)) {
            bytes = in.readNBytes((int) Math.min(Integer.MAX_VALUE - 8, maxBytes + 1));
        } catch (NoSuchFileException e) {
            throw new InputException(source, 0, null, InputProblem.UNREADABLE, what + " file does not exist", null, e);
        } catch (IOException | SecurityException e) {
            throw new InputException(source, 0, null, InputProblem.UNREADABLE,
                    what + " could not be read: " + e.getMessage(), null, e);
        }
        if (bytes.length > maxBytes) {
            throw new InputException(source, 0, null, InputProblem.TOO_LARGE,
                    what + " must be at most " + maxBytes + " bytes, it has more", null);
        }
        return decode(bytes, source, what);
    }

    /**
     * @return {@code bytes} decoded as strict UTF-8
     * @throws InputException ({@link InputProblem#NOT_UTF8}) naming the first bad byte
     */
    public static String decode(byte[] bytes, String source, String what) {
        String utf16 = utf16(bytes);
        if (utf16 != null) {
            throw notUtf8(source, 1, what + " is " + utf16 + "; trajeval reads UTF-8 text (convert it, e.g. "
                    + "iconv -f UTF-16 -t UTF-8)", null);
        }
        CharsetDecoder d = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(bytes.length);
        var result = d.decode(in, out, true);
        if (result.isError()) {
            int at = in.position();
            long line = 1;
            for (int i = 0; i < at; i++) {
                if (bytes[i] == '\n') {
                    line++;
                }
            }
            throw notUtf8(source, line, what + " must be UTF-8 text, byte " + at + " (0x"
                    + String.format("%02X", bytes[at] & 0xff) + ") is not"
                    + (hasNul(bytes) ? ": it looks like a binary file" : " (Latin-1 or another encoding?)"), null);
        }
        d.flush(out);
        out.flip();
        String text = out.toString();
        return text.startsWith("\uFEFF") ? text.substring(1) : text;
    }

    private static boolean hasNul(byte[] bytes) {
        for (byte b : bytes) {
            if (b == 0) {
                return true;
            }
        }
        return false;
    }

    /** @return "UTF-16 (byte-order mark FF FE)" or similar when the head shows UTF-16, else {@code null} */
    public static String utf16(byte[] head) {
        if (head.length >= 2) {
            int a = head[0] & 0xff;
            int b = head[1] & 0xff;
            if (a == 0xff && b == 0xfe) {
                return "UTF-16 text (byte-order mark FF FE)";
            }
            if (a == 0xfe && b == 0xff) {
                return "UTF-16 text (byte-order mark FE FF)";
            }
            if ((a == 0) != (b == 0) && head.length >= 4 && ((head[2] == 0) == (a == 0)) && ((head[3] == 0) == (b == 0))) {
                return "UTF-16 text (every other byte is NUL)";
            }
        }
        return null;
    }

    private static InputException notUtf8(String source, long line, String detail, CharacterCodingException e) {
        return new InputException(source, line, null, InputProblem.NOT_UTF8, detail, null, e);
    }
}
