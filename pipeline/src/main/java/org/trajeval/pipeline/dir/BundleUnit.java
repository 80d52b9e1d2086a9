package org.trajeval.pipeline.dir;

import java.util.ArrayList;
import java.util.List;
import org.trajeval.pipeline.bundle.BareBag;
import org.trajeval.pipeline.bundle.BundleKind;
import org.trajeval.pipeline.bundle.BundleOpener;

/**
 * A bundle as it sits in incoming/: its kind and name, the file names that belong to it and its
 * marker. Its slot in processing/ is named {@code NAME} (folder), {@code NAME.zip} (zip),
 * {@code NAME.pair} (pair) or the bag's file name (bare bag).
 *
 * @param kind folder, zip, pair or bag
 * @param name folder name, zip name without ".zip", the pair's NAME, or the bag's file name ({@code NAME.mcap})
 * @param marker the marker file name, or {@code null} (completed by quiet time)
 */
public record BundleUnit(BundleKind kind, String name, String marker) {
    /** @return the names in incoming/ that make up the payload (moved before the marker) */
    public List<String> payloadNames() {
        return switch (kind) {
            case FOLDER -> List.of(name);
            case ZIP -> List.of(name + ".zip");
            case PAIR -> List.of(name + BundleOpener.PAIR_REFERENCE, name + BundleOpener.PAIR_ESTIMATE);
            case BAG -> List.of(name);
        };
    }

    /** @return every name in incoming/ of this bundle, payload first, marker last */
    public List<String> allNames() {
        List<String> all = new ArrayList<>(payloadNames());
        if (marker != null) {
            all.add(marker);
        } else {
            all.addAll(candidateMarkers());
        }
        return all;
    }

    /** @return the marker names that complete this bundle */
    public List<String> candidateMarkers() {
        return switch (kind) {
            case ZIP -> List.of(name + ".done", name + ".zip.done");
            case BAG -> List.of(BareBag.stem(name) + ".done", name + ".done");
            default -> List.of(name + ".done");
        };
    }

    /** @return the slot folder name in processing/ */
    public String slotName() {
        return switch (kind) {
            case FOLDER -> name;
            case ZIP -> name + ".zip";
            case PAIR -> name + ".pair";
            case BAG -> name;
        };
    }

    /** @return the unit a slot folder name stands for (marker unknown) */
    public static BundleUnit ofSlot(String slot) {
        if (slot.endsWith(".zip")) {
            return new BundleUnit(BundleKind.ZIP, slot.substring(0, slot.length() - 4), null);
        }
        if (BareBag.stem(slot) != null) {
            return new BundleUnit(BundleKind.BAG, slot, null);
        }
        if (slot.endsWith(".pair")) {
            return new BundleUnit(BundleKind.PAIR, slot.substring(0, slot.length() - 5), null);
        }
        return new BundleUnit(BundleKind.FOLDER, slot, null);
    }
}
