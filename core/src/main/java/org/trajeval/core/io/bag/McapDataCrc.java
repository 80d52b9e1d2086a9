package org.trajeval.core.io.bag;

import java.util.zip.CRC32;

/**
 * The data section CRC of an MCAP file (mcap.dev/spec, Data End record, opcode 0x0F, field
 * {@code data_section_crc}): the CRC-32 (IEEE, as {@link CRC32}) of every byte of the file from
 * its first byte (the leading magic included) up to the Data End record, excluded; 0 means "not
 * computed" (rosbag2's writer leaves it 0). This is what the reference writer computes (its
 * CRC writer sees the magic, the header and every data record, then writes the Data End).
 *
 * <p>Worked example: a file of magic (8 bytes), header record (20 bytes), one chunk record
 * (1000 bytes) and the Data End at byte 1028: the CRC covers bytes 0..1027.
 *
 * <p>Verifying reads the whole data section once, in 1 MiB blocks (one sequential pass, no
 * decompression), so a flipped byte in a chunk that no wanted channel uses is found too.
 */
final class McapDataCrc {
    /** Bytes of a Data End record as the spec defines it: opcode, length 4, the CRC. */
    static final int DATA_END_RECORD_BYTES = 1 + 8 + 4;

    private McapDataCrc() {
    }

    /**
     * Checks the data section CRC when the file has one.
     *
     * @param expectedAt where the Data End record should start (the byte before the summary, or
     *     before the footer when there is no summary), or -1 when unknown: the data section is
     *     then walked record by record to find it
     * @throws org.trajeval.core.InputException CORRUPT_BAG naming the Data End's offset on a mismatch,
     *     or a record whose length runs past the file's end
     */
    static void verify(FileWindow file, String source, long expectedAt) {
        long size = file.size();
        if (expectedAt >= McapReader.MAGIC.length && expectedAt + DATA_END_RECORD_BYTES <= size) {
            byte[] rec = file.read(expectedAt, DATA_END_RECORD_BYTES, "Data End record");
            if ((rec[0] & 0xff) == McapReader.OP_DATA_END && ByteCursor.le64(rec, 1) == 4) {
                long stored = ByteCursor.le32(rec, 9) & 0xffffffffL;
                if (stored != 0) {
                    CRC32 crc = new CRC32();
                    file.crc(crc, 0, expectedAt, "the data section");
                    compare(source, expectedAt, crc.getValue(), stored);
                }
                return;
            }
        }
        walk(file, source, size);
    }

    /** Walks the data section's records, feeding each to the CRC, up to the Data End. */
    private static void walk(FileWindow file, String source, long size) {
        CRC32 crc = new CRC32();
        long at = McapReader.MAGIC.length;
        file.crc(crc, 0, at, "magic");
        while (size - at >= 9) {
            byte[] head = file.read(at, 9, "record header");
            int op = head[0] & 0xff;
            long len = ByteCursor.le64(head, 1);
            if (op == McapReader.OP_FOOTER) {
                return; // no Data End record: nothing to compare
            }
            if (len < 0 || len > size - at - 9) {
                throw BagProblems.length(source, at, "record (opcode 0x" + Integer.toHexString(op) + ") length",
                        len, size - at - 9);
            }
            if (op == McapReader.OP_DATA_END) {
                if (len >= 4) {
                    long stored = ByteCursor.le32(file.read(at + 9, 4, "Data End CRC"), 0) & 0xffffffffL;
                    if (stored != 0) {
                        compare(source, at, crc.getValue(), stored);
                    }
                }
                return;
            }
            file.crc(crc, at, 9 + len, "record at byte " + at);
            at += 9 + len;
        }
        // the file ends before a Data End (a recording cut short): nothing to compare
    }

    private static void compare(String source, long dataEndAt, long computed, long stored) {
        if (computed != stored) {
            throw BagProblems.corrupt(source, dataEndAt, String.format("data section CRC mismatch: bytes 0..%d hold "
                    + "CRC 0x%08x but the Data End record says 0x%08x; the file is corrupt (a changed byte "
                    + "somewhere before byte %d)", dataEndAt - 1, computed, stored, dataEndAt));
        }
    }
}
