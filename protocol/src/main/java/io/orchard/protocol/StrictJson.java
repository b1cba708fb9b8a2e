package io.orchard.protocol;

import com.fasterxml.jackson.annotation.JsonInclude;
import java.util.Objects;
import tools.jackson.core.StreamReadConstraints;
import tools.jackson.core.StreamReadFeature;
import tools.jackson.core.StreamWriteFeature;
import tools.jackson.core.json.JsonFactory;
import tools.jackson.databind.DeserializationFeature;
import tools.jackson.databind.MapperFeature;
import tools.jackson.databind.cfg.CoercionAction;
import tools.jackson.databind.cfg.CoercionInputShape;
import tools.jackson.databind.cfg.EnumFeature;
import tools.jackson.databind.json.JsonMapper;
import tools.jackson.databind.type.LogicalType;

/**
 * Orchard's one Jackson configuration: the JSON that comes from outside (protocol lines, scenario
 * and checkpoint files, the glTF a viewer inspects) is read by mappers built here, so they all
 * refuse the same things. Start from {@link #builder()}, add what is particular to the
 * format (the codec's message types, a file's indentation), and {@code build()} once: a built
 * mapper is immutable and safe to share between threads.
 *
 * <p>Reading is strict. Refused: unknown fields (a typo in a hand-written file; the codec turns
 * this off so that newer peers may add fields), a missing record component unless it is
 * {@code @Nullable} ({@link RequiredUnlessNullable}), {@code null} for a number or boolean,
 * duplicate keys at any depth, anything after the document, a fraction where an integer belongs,
 * a string where a number or boolean belongs and the other way round, a number where an enum's
 * name belongs (Jackson would take it for the constant's index), and anything beyond the
 * {@link StreamReadConstraints read limits}: Jackson's defaults, or those given to
 * {@link #builder(StreamReadConstraints)}. Writing leaves out {@code null} values and keeps a
 * record's components in their declared order.
 *
 * <pre>{@code
 * JsonMapper mapper = StrictJson.builder(StreamReadConstraints.builder()
 *         .maxNestingDepth(64).maxDocumentLength(4 << 20).build()).build();
 * JsonNode tree = mapper.readTree(json); // refused past 64 levels, naming the limit
 * }</pre>
 */
public final class StrictJson {

    private StrictJson() {}

    /** A builder with the strict configuration and Jackson's default read limits. */
    public static JsonMapper.Builder builder() {
        return builder(StreamReadConstraints.defaults());
    }

    /**
     * A builder with the strict configuration and these read limits: how deep a document may nest,
     * and how long it, its strings, its numbers and its names may be. Over a limit, reading throws
     * a {@code StreamConstraintsException} whose message names the limit and the value.
     */
    public static JsonMapper.Builder builder(StreamReadConstraints constraints) {
        Objects.requireNonNull(constraints, "constraints");
        JsonFactory factory = JsonFactory.builder().streamReadConstraints(constraints).build();
        return JsonMapper.builder(factory)
                .annotationIntrospector(new RequiredUnlessNullable())
                .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES)
                .enable(DeserializationFeature.FAIL_ON_NULL_FOR_PRIMITIVES)
                .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
                .enable(DeserializationFeature.FAIL_ON_INVALID_SUBTYPE)
                .disable(DeserializationFeature.ACCEPT_FLOAT_AS_INT)
                .disable(MapperFeature.ALLOW_COERCION_OF_SCALARS)
                .enable(EnumFeature.FAIL_ON_NUMBERS_FOR_ENUMS)
                .disable(MapperFeature.SORT_PROPERTIES_ALPHABETICALLY)
                .enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION)
                .enable(StreamReadFeature.USE_FAST_DOUBLE_PARSER)
                .enable(StreamWriteFeature.USE_FAST_DOUBLE_WRITER)
                .withCoercionConfig(LogicalType.Textual, strings -> strings
                        .setCoercion(CoercionInputShape.Integer, CoercionAction.Fail)
                        .setCoercion(CoercionInputShape.Float, CoercionAction.Fail)
                        .setCoercion(CoercionInputShape.Boolean, CoercionAction.Fail))
                .changeDefaultPropertyInclusion(inclusion -> inclusion
                        .withValueInclusion(JsonInclude.Include.NON_NULL)
                        .withContentInclusion(JsonInclude.Include.NON_NULL));
    }
}
