package io.orchard.viewer.world;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import io.orchard.protocol.message.WorldSnapshotMessage;
import io.orchard.protocol.value.Point2;
import io.orchard.server.world.WorldGenerator;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

class PolygonsTest {

    static final List<Point2> SQUARE = List.of(new Point2(0, 0), new Point2(4, 0), new Point2(4, 4), new Point2(0, 4));
    static final List<Point2> ELL = List.of(new Point2(0, 0), new Point2(6, 0), new Point2(6, 2), new Point2(2, 2),
            new Point2(2, 6), new Point2(0, 6));

    static Stream<Arguments> polygons() {
        WorldSnapshotMessage world = WorldGenerator.standard(1998).generate().snapshot(0, 0, List.of());
        List<Point2> reversed = new ArrayList<>(ELL);
        Collections.reverse(reversed);
        return Stream.of(
                Arguments.of("square", SQUARE),
                Arguments.of("L shape", ELL),
                Arguments.of("L shape, other way round", reversed),
                Arguments.of("castle of seed 1998", world.castle().footprint()),
                Arguments.of("river of seed 1998", world.river().outline()));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("polygons")
    void triangulationCoversTheAreaExactly(String name, List<Point2> polygon) {
        int[] triangles = Polygons.triangulate(polygon);

        assertThat(triangles).hasSize((polygon.size() - 2) * 3);
        double area = 0;
        for (int t = 0; t < triangles.length; t += 3) {
            double part = Polygons.signedArea(List.of(polygon.get(triangles[t]), polygon.get(triangles[t + 1]),
                    polygon.get(triangles[t + 2])));
            assertThat(Math.signum(part)).as("triangle %d winds like the polygon", t / 3)
                    .isEqualTo(Math.signum(Polygons.signedArea(polygon)));
            area += Math.abs(part);
        }
        assertThat(area).isCloseTo(Math.abs(Polygons.signedArea(polygon)), within(1e-6));
    }

    @Test
    void containsAndSegmentsFollowTheOutline() {
        assertThat(Polygons.contains(ELL, 1, 5)).isTrue();
        assertThat(Polygons.contains(ELL, 4, 4)).isFalse();
        assertThat(Polygons.segmentTouches(ELL, 4, 4, 5, 5)).isFalse();
        assertThat(Polygons.segmentTouches(ELL, 4, 4, 4, -1)).isTrue();
        assertThat(Polygons.segmentTouches(SQUARE, 1, 1, 2, 2)).as("inside entirely").isTrue();
    }

    @Test
    void convexHullKeepsTheOuterCorners() {
        assertThat(Polygons.convexHull(ELL)).containsExactlyInAnyOrder(new Point2(0, 0), new Point2(6, 0),
                new Point2(6, 2), new Point2(2, 6), new Point2(0, 6));
    }

    @Test
    void centroidOfASquareIsItsMiddle() {
        assertThat(Polygons.centroid(SQUARE)).isEqualTo(new Point2(2, 2));
    }

    @Test
    void tooFewPointsAreRefused() {
        assertThatThrownBy(() -> Polygons.triangulate(List.of(new Point2(0, 0), new Point2(1, 1))))
                .hasMessage("a polygon needs at least 3 points, has 2");
    }
}
