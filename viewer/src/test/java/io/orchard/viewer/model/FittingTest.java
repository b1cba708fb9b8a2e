package io.orchard.viewer.model;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.assertj.core.api.Assertions.within;

import com.jme3.bounding.BoundingBox;
import com.jme3.math.Vector3f;
import io.orchard.protocol.value.ModelFormat;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Models as real files come, fitted to the body: the test figure (1.6 m tall, its flag making it
 * 1 m wide from x = -0.25 to 0.75) authored in centimetres, shifted off its origin, or both; after
 * fitting, and placed where the agent is, it stands on y = 0, as tall as the body, centred on the
 * agent's place, and still moves in metres.
 */
class FittingTest {

    @ParameterizedTest(name = "{0}: {1}")
    @CsvSource(delimiter = '|', textBlock = """
            Figure   | "scale": [100, 100, 100],
            Figure   | "translation": [3, -1, 2],
            Stranger | "translation": [3, -1, 2], "scale": [100, 100, 100],
            Stranger | ''
            """)
    void theModelStandsOnTheGroundAsTallAsTheBodyAtItsPlace(String agent, String transform) throws ModelException {
        BodyModel model = TestModels.load(agent, ModelFormat.GLTF, SkinnedFigure.embedded(transform));

        model.fitToHeight(2.4);
        model.moveTo(Vector3f.ZERO, Vector3f.ZERO, 0, 0); // as the viewer places every model it shows
        model.update(0);

        BoundingBox box = bounds(model);
        assertThat(box.getYExtent() * 2).as("height").isCloseTo(2.4f, within(1e-3f));
        assertThat(box.getCenter().y - box.getYExtent()).as("feet").isCloseTo(0f, within(1e-3f));
        assertThat(box.getCenter().x).as("centre x").isCloseTo(0f, within(1e-3f));
        assertThat(box.getCenter().z).as("centre z").isCloseTo(0f, within(1e-3f));
        assertThat(box.getXExtent() * 2).as("width, in proportion").isCloseTo(1.5f, within(1e-3f));
    }

    @Test
    void aFittedModelStillMovesInMetres() throws ModelException {
        BodyModel model = TestModels.load("Figure", ModelFormat.GLTF,
                SkinnedFigure.embedded("\"scale\": [100, 100, 100], "));
        model.fitToHeight(1.6);

        model.moveTo(new Vector3f(0, 0, 0), new Vector3f(4, 0, -6), 0, 2);
        model.update(2);

        BoundingBox box = bounds(model);
        assertThat(box.getCenter().x).isCloseTo(4f, within(1e-3f));
        assertThat(box.getCenter().z).isCloseTo(-6f, within(1e-3f));
        assertThat(box.getYExtent() * 2).isCloseTo(1.6f, within(1e-3f));
    }

    @Test
    void aHeightThatIsNoHeightIsRefused() throws ModelException {
        BodyModel model = TestModels.load("Figure", ModelFormat.GLTF, SkinnedFigure.embedded());

        assertThatThrownBy(() -> model.fitToHeight(0)).isInstanceOf(ModelException.class)
                .hasMessageContaining("positive number of metres but is 0.0");
    }

    private static BoundingBox bounds(BodyModel model) {
        model.root().updateGeometricState();
        return (BoundingBox) model.root().getWorldBound();
    }
}
