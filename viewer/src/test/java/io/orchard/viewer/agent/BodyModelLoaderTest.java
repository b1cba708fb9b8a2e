package io.orchard.viewer.agent;

import static org.assertj.core.api.Assertions.assertThat;

import com.jme3.asset.AssetManager;
import com.jme3.asset.DesktopAssetManager;
import com.jme3.math.Vector3f;
import com.jme3.scene.Spatial;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.protocol.value.ModelSpec;
import io.orchard.viewer.model.BodyModel;
import io.orchard.viewer.model.ModelLimits;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class BodyModelLoaderTest {

    static final AssetManager ASSETS = new DesktopAssetManager(true);
    private final BodyModelLoader loader = new BodyModelLoader(ASSETS, ModelLimits.DEFAULTS);

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"figure", "bunny"})
    void bundledModelsLoadUnderTheAgentsName(String bundled) {
        BodyModelLoader.Loaded loaded = loader.load("Guppy", 1.2, ModelSpec.bundled(bundled));

        assertThat(loaded.problem()).isNull();
        BodyModel model = loaded.model();
        assertThat(model.isPlaceholder()).isFalse();
        assertThat(model.hasNode("Guppy")).isTrue();
        assertThat(model.hasNode("GuppyMover")).isTrue();
        assertThat(model.hasNode("GuppyTSMover")).isTrue();
        assertThat(model.animationNames()).contains("GuppyTSGrasp");
        assertThat(model.hasNode(bundled.substring(0, 1).toUpperCase() + bundled.substring(1))).isFalse();
    }

    @Test
    void theFigureHasTheDocumentedJointsAndWalk() {
        BodyModel figure = loader.load("Guppy", 1.7, ModelSpec.bundled("figure")).model();

        assertThat(figure.jointNames()).contains("Neck", "LeftShoulder", "LeftElbow", "RightShoulder", "RightElbow",
                "LeftHip", "LeftKnee", "RightHip", "RightKnee", "GuppyBody");
        assertThat(figure.animationNames()).contains("GuppyTSWalk", "GuppyTSGrasp");
    }

    @Test
    void bundledModelsAreSizedToTheBody() {
        Spatial tall = loader.load("Tall", 3.4, ModelSpec.bundled("figure")).model().root().getChild("TallSize");
        Spatial plain = loader.load("Plain", 1.7, ModelSpec.bundled("figure")).model().root().getChild("PlainSize");

        assertThat(tall.getLocalScale().y).isEqualTo(2f);
        assertThat(plain.getLocalScale()).isEqualTo(new Vector3f(1, 1, 1));
    }

    @Test
    void moveToCarriesTheBundledFigureThroughItsMover() throws Exception {
        BodyModel figure = loader.load("Guppy", 1.7, ModelSpec.bundled("figure")).model();
        Spatial body = figure.root().getChild("Guppy");
        figure.update(0);

        figure.moveTo(new Vector3f(0, 0, 0), new Vector3f(4, 0, -8), 1, 2);
        figure.update(2);

        assertThat(body.getLocalTranslation()).isEqualTo(new Vector3f(2, 0, -4));
    }

    @Test
    void anUnknownBundledNameGivesAPlaceholderAndSaysWhichExist() {
        BodyModelLoader.Loaded loaded = loader.load("Guppy", 1.2, ModelSpec.bundled("dragon"));

        assertThat(loaded.model().isPlaceholder()).isTrue();
        assertThat(loaded.model().hasNode("Guppy")).isTrue();
        assertThat(loaded.problem()).isEqualTo("there is no bundled model named 'dragon'; the viewer ships figure, bunny");
    }

    @Test
    void aBrokenModelGivesAPlaceholderAndTheLoadersReason() {
        byte[] broken = "<X3D><Scene><Transform DEF='Guppy'>".getBytes(StandardCharsets.UTF_8);

        BodyModelLoader.Loaded loaded = loader.load("Guppy", 1.2, ModelSpec.of(ModelFormat.X3D, broken));

        assertThat(loaded.model().isPlaceholder()).isTrue();
        assertThat(loaded.problem()).containsIgnoringCase("X3D");
    }

    @Test
    void aModelWithNothingToDrawGivesAPlaceholderAndSaysWhy() {
        byte[] proto = ("<X3D><Scene><ExternProtoDeclare name='Body' url='\"https://example.org/body.x3d\"'/>"
                + "<Transform DEF='Guppy'><ProtoInstance name='Body'/>"
                + "<Shape><Text string='\"Guppy\"'/></Shape></Transform></Scene></X3D>").getBytes(StandardCharsets.UTF_8);

        BodyModelLoader.Loaded loaded = loader.load("Guppy", 1.2, ModelSpec.of(ModelFormat.X3D, proto));

        assertThat(loaded.model().isPlaceholder()).isTrue();
        assertThat(loaded.problem()).startsWith("the x3d model has nothing to draw")
                .contains("instances of an ExternProtoDeclare");
    }

    @Test
    void noModelGivesAPlaceholderWithoutAProblem() {
        BodyModelLoader.Loaded loaded = loader.load("Guppy", 1.2, null);

        assertThat(loaded.model().isPlaceholder()).isTrue();
        assertThat(loaded.problem()).isNull();
    }

    @Test
    void renamingTouchesOnlyNamesThatStartWithTheModelsName() {
        String fitted = BundledModels.fit("<Transform DEF='FigureSize'/><Transform DEF='Neck'/>"
                + "<ROUTE fromNode='FigureTSWalk' toNode='WalkLeftHip'/><Shape><Appearance USE='Shirt'/></Shape>",
                "Figure", "Guppy", 1.7);

        assertThat(fitted).isEqualTo("<Transform DEF='GuppySize' scale='1.0000 1.0000 1.0000'/><Transform DEF='Neck'/>"
                + "<ROUTE fromNode='GuppyTSWalk' toNode='WalkLeftHip'/><Shape><Appearance USE='Shirt'/></Shape>");
    }
}
