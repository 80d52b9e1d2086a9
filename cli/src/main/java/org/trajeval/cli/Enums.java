package org.trajeval.cli;

import java.util.Locale;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.TimeUnit;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.metric.PairsFrom;
import org.trajeval.core.metric.RpeUnit;
import picocli.CommandLine.ITypeConverter;
import picocli.CommandLine.TypeConversionException;

/** Case-insensitive converters from command-line words to the core's enums, with clear refusals. */
final class Enums {
    private Enums() {
    }

    static <E extends Enum<E>> E parse(Class<E> type, String word, String allowed) {
        String key = word.trim().toUpperCase(Locale.ROOT).replace('-', '_');
        for (E e : type.getEnumConstants()) {
            if (e.name().equals(key)) {
                return e;
            }
        }
        throw new TypeConversionException("expected one of " + allowed + ", found \"" + word + "\"");
    }

    /** lesson|evo|kitti. */
    static final class ConventionConverter implements ITypeConverter<Convention> {
        @Override
        public Convention convert(String v) {
            return parse(Convention.class, v, "lesson|evo|kitti");
        }
    }

    /** interpolate|nearest|nearest-interpolated. */
    static final class AssociationConverter implements ITypeConverter<AssociationMethod> {
        @Override
        public AssociationMethod convert(String v) {
            return parse(AssociationMethod.class, v, "interpolate|nearest|nearest-interpolated");
        }
    }

    /** crop|strict. */
    static final class OverlapConverter implements ITypeConverter<OverlapPolicy> {
        @Override
        public OverlapPolicy convert(String v) {
            return parse(OverlapPolicy.class, v, "crop|strict");
        }
    }

    /** none|se2|sim2|se3|sim3|origin|posyaw. */
    static final class AlignmentConverter implements ITypeConverter<AlignmentModel> {
        @Override
        public AlignmentModel convert(String v) {
            return parse(AlignmentModel.class, v, "none|se2|sim2|se3|sim3|origin|posyaw");
        }
    }

    /** s|frames|m. */
    static final class RpeUnitConverter implements ITypeConverter<RpeUnit> {
        @Override
        public RpeUnit convert(String v) {
            for (RpeUnit u : RpeUnit.values()) {
                if (u.symbol().equalsIgnoreCase(v.trim())) {
                    return u;
                }
            }
            throw new TypeConversionException("expected one of s|frames|m, found \"" + v + "\"");
        }
    }

    /** reference|estimate. */
    static final class PairsFromConverter implements ITypeConverter<PairsFrom> {
        @Override
        public PairsFrom convert(String v) {
            return parse(PairsFrom.class, v, "reference|estimate");
        }
    }

    /** auto|csv|tum|kitti|euroc; auto gives null. */
    static final class FormatConverter implements ITypeConverter<TrajectoryFormat> {
        @Override
        public TrajectoryFormat convert(String v) {
            if ("auto".equalsIgnoreCase(v.trim())) {
                return null;
            }
            return parse(TrajectoryFormat.class, v, "auto|csv|tum|kitti|euroc");
        }
    }

    /** refuse|keep. */
    static final class DuplicatesConverter implements ITypeConverter<DuplicateTimestamps> {
        @Override
        public DuplicateTimestamps convert(String v) {
            return parse(DuplicateTimestamps.class, v, "refuse|keep");
        }
    }

    /** s|ms|us|ns. */
    static final class TimeUnitConverter implements ITypeConverter<TimeUnit> {
        @Override
        public TimeUnit convert(String v) {
            return parse(TimeUnit.class, v, "s|ms|us|ns");
        }
    }

    static final class PlotPlaneConverter implements ITypeConverter<org.trajeval.figures.PlotPlane> {
        @Override
        public org.trajeval.figures.PlotPlane convert(String v) {
            return parse(org.trajeval.figures.PlotPlane.class, v, "auto|xy|xz|yz");
        }
    }

    static final class ResFormatConverter implements ITypeConverter<ResTable.Format> {
        @Override
        public ResTable.Format convert(String v) {
            return parse(ResTable.Format.class, v, "table|csv|markdown|latex");
        }
    }
}
