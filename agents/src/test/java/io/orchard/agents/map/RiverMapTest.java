package io.orchard.agents.map;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import io.orchard.protocol.value.Point2;
import org.junit.jupiter.api.Test;

/** A river running east-west between z = 10 and z = 20. */
class RiverMapTest {

    private static final double EAST = -Math.PI / 2;

    private final RiverMap river = new RiverMap();

    private void seeNorthBankFrom(double x) {
        river.sighted(new ShoreSighting(new Point2(x, 0), new Point2(x, 10), EAST));
    }

    private void seeSouthBankFrom(double x) {
        river.sighted(new ShoreSighting(new Point2(x, 30), new Point2(x, 20), EAST));
    }

    @Test
    void anUnseenRiverIsNowhere() {
        assertThat(river.seen()).isFalse();
        assertThat(river.water(0, 15, 0)).isFalse();
        assertThat(river.side(0, 15, 0)).isEqualTo(RiverMap.Side.UNKNOWN);
    }

    @Test
    void oneBankSeenMakesABandOfTheDefaultWidthBeyondIt() {
        seeNorthBankFrom(0);
        seeNorthBankFrom(10);

        assertThat(river.water(5, 12, 0)).isTrue();
        assertThat(river.water(5, 10 + RiverMap.DEFAULT_WIDTH - 0.5, 0)).isTrue();
        assertThat(river.water(5, 8, 0)).isFalse();
        assertThat(river.water(5, 8, 2.5)).isTrue(); // within the margin
        assertThat(river.side(5, 5, 0)).isEqualTo(RiverMap.Side.LOW);
        assertThat(river.side(5, 40, 0)).isEqualTo(RiverMap.Side.HIGH);
    }

    @Test
    void bothBanksSeenMeasureTheWidth() {
        seeNorthBankFrom(0);
        seeNorthBankFrom(20);
        seeSouthBankFrom(5);
        seeSouthBankFrom(15);

        assertThat(river.width()).isCloseTo(10, within(1e-9));
        assertThat(river.water(10, 19.5, 0)).isTrue();
        assertThat(river.water(10, 20.5, 0)).isFalse();
    }

    @Test
    void theBandReachesOnlySoFarBeyondWhatWasSeen() {
        seeNorthBankFrom(0);

        assertThat(river.water(RiverMap.EXTRAPOLATION - 1, 12, 0)).isTrue();
        assertThat(river.water(RiverMap.EXTRAPOLATION + 1, 12, 0)).isFalse();
    }

    @Test
    void aBridgeTellsWhereTheRiverCrosses() {
        river.bridged(new KnownBridge("B1", new Point2(30, 8), new Point2(30, 22), 4));

        assertThat(river.water(30, 15, 0)).isTrue();
        assertThat(river.water(40, 15, 0)).isTrue();
        assertThat(river.water(30, 5, 0)).isFalse();
        assertThat(river.water(30, 25, 0)).isFalse();
    }

    @Test
    void sightingsOfTheSamePointFromFartherAwayAreNotKept() {
        seeNorthBankFrom(0);
        long version = river.version();

        river.sighted(new ShoreSighting(new Point2(0, -20), new Point2(0.2, 10), EAST));

        assertThat(river.version()).isEqualTo(version);
        assertThat(river.sightings()).hasSize(1);
    }
}
