package io.orchard.server.world.scenario;

import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import tools.jackson.core.JacksonException;

/**
 * Which record a place in a scenario file is read into, found by following the path through the
 * records' components and the element types of their lists. A scenario is made of records and
 * lists of records only, and their JSON fields are named as their components.
 */
final class RecordTypes {

    private RecordTypes() {}

    /** The record type at the path from the root type, if the path leads to a record. */
    static Optional<Class<?>> at(Class<?> root, List<JacksonException.Reference> path) {
        Type type = root;
        for (JacksonException.Reference reference : path) {
            if (reference.getPropertyName() != null) {
                Optional<Type> component = raw(type).filter(Class::isRecord)
                        .flatMap(record -> Stream.of(record.getRecordComponents())
                                .filter(c -> c.getName().equals(reference.getPropertyName()))
                                .map(RecordComponent::getGenericType)
                                .findFirst());
                if (component.isEmpty()) {
                    return Optional.empty();
                }
                type = component.get();
            } else if (type instanceof ParameterizedType list && raw(list).filter(List.class::equals).isPresent()) {
                type = list.getActualTypeArguments()[0];
            } else {
                return Optional.empty();
            }
        }
        return raw(type).filter(Class::isRecord);
    }

    /** The JSON field names of a record: its components' names. */
    static List<String> fields(Class<?> record) {
        return Stream.of(record.getRecordComponents()).map(RecordComponent::getName).toList();
    }

    private static Optional<Class<?>> raw(Type type) {
        if (type instanceof Class<?> plain) {
            return Optional.of(plain);
        }
        if (type instanceof ParameterizedType parameterized && parameterized.getRawType() instanceof Class<?> raw) {
            return Optional.of(raw);
        }
        return Optional.empty();
    }
}
