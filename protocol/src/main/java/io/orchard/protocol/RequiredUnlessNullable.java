package io.orchard.protocol;

import io.orchard.protocol.value.Nullable;
import tools.jackson.databind.cfg.MapperConfig;
import tools.jackson.databind.introspect.AnnotatedMember;
import tools.jackson.databind.introspect.AnnotatedParameter;
import tools.jackson.databind.introspect.JacksonAnnotationIntrospector;

/**
 * Makes every record component required on the wire unless it is marked {@link Nullable}. Without
 * this, a missing number would silently decode as 0 and a missing coordinate would move an agent
 * to the origin. {@link StrictJson} applies it to every mapper, so that other JSON formats built on
 * the protocol's records (scenario and checkpoint files) read them by the same rule.
 */
public final class RequiredUnlessNullable extends JacksonAnnotationIntrospector {

    private static final long serialVersionUID = 1L;

    @Override
    public Boolean hasRequiredMarker(MapperConfig<?> config, AnnotatedMember member) {
        if (member instanceof AnnotatedParameter) {
            return !member.hasAnnotation(Nullable.class);
        }
        return super.hasRequiredMarker(config, member);
    }
}
