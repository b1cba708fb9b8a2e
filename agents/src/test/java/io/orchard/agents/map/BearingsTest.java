package io.orchard.agents.map;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import io.orchard.protocol.value.Point2;
import io.orchard.protocol.value.RelativePosition;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class BearingsTest {

    @ParameterizedTest(name = "facing {2}: a thing {3} away at bearing {4} stands at ({5}, {6})")
    @CsvSource({
            // self x, z, heading, distance, bearing, world x, z
            "0, 0, 0, 10, 1.5707963267948966, -10, 0",   // the protocol's worked example: to the left is west
            "0, 0, 1.5707963267948966, 10, 0, -10, 0",   // facing west, straight ahead
            "0, 0, 0, 10, 3.141592653589793, 0, 10",     // behind is south
            "5, -5, -1.5707963267948966, 4, 0, 9, -5",   // facing east
            "5, -5, 3.141592653589793, 2, -1.5707963267948966, 3, -5" // facing south, the right hand points west
    })
    void relativePositionsBecomeWorldPositions(double x, double z, double heading, double distance, double bearing,
                                               double wx, double wz) {
        Point2 world = Bearings.toWorld(new Point2(x, z), heading, new RelativePosition(distance, bearing));

        assertThat(world.x()).isCloseTo(wx, within(1e-9));
        assertThat(world.z()).isCloseTo(wz, within(1e-9));
    }

    @ParameterizedTest(name = "from heading {0} to ({1}, {2}) and back")
    @CsvSource({"0, 3, 4", "2.5, -7, 1", "-3, 0.5, -9", "3.141592653589793, 10, 10"})
    void toRelativeAndBackIsTheIdentity(double heading, double x, double z) {
        Point2 self = new Point2(1, 2);
        RelativePosition relative = Bearings.toRelative(self, heading, new Point2(x, z));

        Point2 back = Bearings.toWorld(self, heading, relative);

        assertThat(relative.bearing()).isBetween(-Math.PI, Math.PI);
        assertThat(back.x()).isCloseTo(x, within(1e-9));
        assertThat(back.z()).isCloseTo(z, within(1e-9));
    }

    @ParameterizedTest(name = "heading {0} faces ({1}, {2})")
    @CsvSource({"0, 0, -1", "1.5707963267948966, -1, 0", "-1.5707963267948966, 1, 0", "3.141592653589793, 0, 1"})
    void aHeadingFacesMinusSinMinusCos(double heading, double dx, double dz) {
        Point2 ahead = Bearings.ahead(new Point2(0, 0), heading, 1);

        assertThat(ahead.x()).isCloseTo(dx, within(1e-9));
        assertThat(ahead.z()).isCloseTo(dz, within(1e-9));
        assertThat(Bearings.headingOf(dx, dz)).isCloseTo(heading, within(1e-9));
    }
}
