package io.orchard.viewer.model.build;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;

import com.jme3.bounding.BoundingBox;
import com.jme3.material.Material;
import com.jme3.material.RenderState.BlendMode;
import com.jme3.material.RenderState.FaceCullMode;
import com.jme3.math.ColorRGBA;
import com.jme3.math.FastMath;
import com.jme3.math.Quaternion;
import com.jme3.math.Vector3f;
import com.jme3.renderer.queue.RenderQueue.Bucket;
import com.jme3.scene.Geometry;
import com.jme3.scene.Mesh;
import com.jme3.scene.Node;
import com.jme3.scene.Spatial;
import com.jme3.scene.VertexBuffer;
import com.jme3.texture.Texture;
import io.orchard.protocol.value.ModelFormat;
import io.orchard.viewer.model.BodyModel;
import io.orchard.viewer.model.TestModels;
import io.orchard.viewer.model.event.LiveMaterial;
import java.nio.FloatBuffer;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Each supported node type, written once in VRML97 and once in X3D, built into jME spatials; the
 * same assertions hold for both encodings.
 */
class NodeBuildingTest {

    /** An assertion on a loaded model. */
    interface Check {
        void verify(BodyModel model) throws Exception;
    }

    private record Case(String name, String vrml, String x3d, Check check) {
    }

    private static final String RED_PNG = TestModels.pngDataUri(2, 2, 0xff0000);
    private static final String GIF = "data:image/gif;base64,R0lGODlhAQABAAAAACw=";
    private static final String BLUE_JPEG = TestModels.imageDataUri("jpeg", 8, 4, 0x0000ff);

    private static final String SQUARE_POINTS = "0 0 0, 1 0 0, 1 0 -1, 0 0 -1";

    private static List<Case> cases() {
        return List.of(
                new Case("Transform translation, rotation and scale",
                        "DEF Arm Transform { translation 1 2 3 rotation 0 1 0 1.5707963"
                                + " scale 2 2 2 }",
                        "<Transform DEF='Arm' translation='1 2 3' rotation='0 1 0 1.5707963'"
                                + " scale='2 2 2'/>",
                        model -> {
                            Spatial arm = TestModels.find(model.root(), "Arm");
                            assertThat(arm).isInstanceOf(Node.class);
                            assertThat(arm.getLocalTranslation()).isEqualTo(new Vector3f(1, 2, 3));
                            assertRotation(arm, Vector3f.UNIT_Y, FastMath.HALF_PI);
                            assertThat(arm.getLocalScale()).isEqualTo(new Vector3f(2, 2, 2));
                        }),
                new Case("Transform rotating about its center",
                        "DEF Hinge Transform { center 0 1 0 rotation 0 0 1 3.14159265 }",
                        "<Transform DEF='Hinge' center='0 1 0' rotation='0 0 1 3.14159265'/>",
                        model -> {
                            Spatial hinge = TestModels.find(model.root(), "Hinge");
                            assertClose(hinge.getLocalTranslation(), new Vector3f(0, 2, 0));
                        }),
                new Case("Transform with a scale orientation scales along its own axes",
                        "DEF Skew Transform { scale 2 1 1 scaleOrientation 0 0 1 1.5707963"
                                + " children DEF Tip Transform { } }",
                        "<Transform DEF='Skew' scale='2 1 1' scaleOrientation='0 0 1 1.5707963'>"
                                + "<Transform DEF='Tip'/></Transform>",
                        model -> {
                            Spatial skew = TestModels.find(model.root(), "Skew");
                            assertThat(skew.getLocalScale()).isEqualTo(new Vector3f(2, 1, 1));
                            assertThat(skew.getLocalRotation().isIdentity()).isTrue();
                            assertThat(TestModels.find(model.root(), "Tip").getParent())
                                    .isSameAs(skew);
                        }),
                new Case("Group of shapes",
                        "DEF Body Group { children [ Shape { geometry Box {} }"
                                + " Shape { geometry Sphere {} } ] }",
                        "<Group DEF='Body'><Shape><Box/></Shape><Shape><Sphere/></Shape></Group>",
                        model -> {
                            Node body = (Node) TestModels.find(model.root(), "Body");
                            assertThat(body.getChildren()).extracting(Spatial::getName)
                                    .containsExactly("Box", "Sphere");
                        }),
                new Case("Material colours on a lit shape",
                        "DEF Red Shape { appearance Appearance { material Material {"
                                + " diffuseColor 1 0 0 specularColor 0.5 0.5 0.5 shininess 0.5"
                                + " emissiveColor 0 0 0.1 transparency 0.25 } } geometry Box {} }",
                        "<Shape DEF='Red'><Appearance><Material diffuseColor='1 0 0'"
                                + " specularColor='0.5 0.5 0.5' shininess='0.5'"
                                + " emissiveColor='0 0 0.1' transparency='0.25'/></Appearance>"
                                + "<Box/></Shape>",
                        model -> {
                            Geometry red = (Geometry) TestModels.find(model.root(), "Red");
                            Material m = red.getMaterial();
                            assertThat(m.getMaterialDef().getAssetName()).isEqualTo(
                                    LiveMaterial.LIGHTING);
                            assertThat((Boolean) m.getParamValue("UseMaterialColors")).isTrue();
                            assertColor(m, "Diffuse", new ColorRGBA(1, 0, 0, 0.75f));
                            assertColor(m, "Ambient", new ColorRGBA(0.2f, 0, 0.1f, 0.75f));
                            assertColor(m, "Specular", new ColorRGBA(0.5f, 0.5f, 0.5f, 1));
                            assertThat((Float) m.getParamValue("Shininess")).isEqualTo(64f);
                            assertThat(m.getAdditionalRenderState().getBlendMode())
                                    .isEqualTo(BlendMode.Alpha);
                            assertThat(red.getQueueBucket()).isEqualTo(Bucket.Transparent);
                        }),
                new Case("Shape without appearance is unlit white",
                        "Shape { geometry Box {} }",
                        "<Shape><Box/></Shape>",
                        model -> {
                            Material m = ((Geometry) TestModels.find(model.root(), "Box"))
                                    .getMaterial();
                            assertThat(m.getMaterialDef().getAssetName()).isEqualTo(
                                    LiveMaterial.UNSHADED);
                            assertColor(m, "Color", ColorRGBA.White);
                        }),
                new Case("Material with only an emissive colour is unshaded",
                        "Shape { appearance Appearance { material Material { diffuseColor 0 0 0"
                                + " emissiveColor 0 1 0 } } geometry Sphere {} }",
                        "<Shape><Appearance><Material diffuseColor='0 0 0' emissiveColor='0 1 0'/>"
                                + "</Appearance><Sphere/></Shape>",
                        model -> {
                            Material m = ((Geometry) TestModels.find(model.root(), "Sphere"))
                                    .getMaterial();
                            assertThat(m.getMaterialDef().getAssetName()).isEqualTo(
                                    LiveMaterial.UNSHADED);
                            assertColor(m, "Color", ColorRGBA.Green);
                        }),
                new Case("ImageTexture from an embedded PNG",
                        "Shape { appearance Appearance { material Material {}"
                                + " texture ImageTexture { url \"" + RED_PNG + "\" repeatS FALSE }"
                                + " } geometry Box {} }",
                        "<Shape><Appearance><Material/><ImageTexture url='\"" + RED_PNG + "\"'"
                                + " repeatS='false'/></Appearance><Box/></Shape>",
                        model -> {
                            Material m = ((Geometry) TestModels.find(model.root(), "Box"))
                                    .getMaterial();
                            Texture texture = (Texture) m.getParamValue("DiffuseMap");
                            assertThat(texture.getImage().getWidth()).isEqualTo(2);
                            assertThat(texture.getWrap(Texture.WrapAxis.S))
                                    .isEqualTo(Texture.WrapMode.EdgeClamp);
                            assertThat(texture.getWrap(Texture.WrapAxis.T))
                                    .isEqualTo(Texture.WrapMode.Repeat);
                            assertColor(m, "Diffuse", ColorRGBA.White);
                        }),
                new Case("ImageTexture from an embedded JPEG on an unlit shape",
                        "Shape { appearance Appearance { texture ImageTexture { url \""
                                + BLUE_JPEG + "\" } } geometry Sphere {} }",
                        "<Shape><Appearance><ImageTexture url='\"" + BLUE_JPEG + "\"'/>"
                                + "</Appearance><Sphere/></Shape>",
                        model -> {
                            Material m = ((Geometry) TestModels.find(model.root(), "Sphere"))
                                    .getMaterial();
                            Texture texture = (Texture) m.getParamValue("ColorMap");
                            assertThat(texture.getImage().getWidth()).isEqualTo(8);
                            assertThat(texture.getImage().getHeight()).isEqualTo(4);
                        }),
                new Case("ImageTexture with a remote URL is ignored, not fetched",
                        "Shape { appearance Appearance { material Material {} texture"
                                + " ImageTexture { url [ \"http://127.0.0.1:9/skin.png\""
                                + " \"skin.png\" ] } } geometry Box {} }",
                        "<Shape><Appearance><Material/><ImageTexture"
                                + " url='\"http://127.0.0.1:9/skin.png\" \"skin.png\"'/>"
                                + "</Appearance><Box/></Shape>",
                        model -> {
                            Material m = ((Geometry) TestModels.find(model.root(), "Box"))
                                    .getMaterial();
                            assertThat(m.getParam("DiffuseMap")).isNull();
                        }),
                new Case("ImageTexture in another image format is ignored",
                        "Shape { appearance Appearance { material Material {} texture"
                                + " ImageTexture { url \"" + GIF + "\""
                                + " } } geometry Box {} }",
                        "<Shape><Appearance><Material/><ImageTexture"
                                + " url='\"" + GIF + "\"'/>"
                                + "</Appearance><Box/></Shape>",
                        model -> assertThat(((Geometry) TestModels.find(model.root(), "Box"))
                                .getMaterial().getParam("DiffuseMap")).isNull()),
                new Case("Box of a given size",
                        "Shape { geometry Box { size 2 4 6 } }",
                        "<Shape><Box size='2 4 6'/></Shape>",
                        model -> {
                            Mesh mesh = mesh(model, "Box");
                            assertThat(mesh.getVertexCount()).isEqualTo(24);
                            assertThat(mesh.getTriangleCount()).isEqualTo(12);
                            BoundingBox box = (BoundingBox) mesh.getBound();
                            assertThat(box.getExtent(null)).isEqualTo(new Vector3f(1, 2, 3));
                        }),
                new Case("Box with VRML's default size",
                        "Shape { geometry Box {} }",
                        "<Shape><Box/></Shape>",
                        model -> assertThat(((BoundingBox) mesh(model, "Box").getBound())
                                .getExtent(null)).isEqualTo(new Vector3f(1, 1, 1))),
                new Case("Sphere of a given radius",
                        "Shape { geometry Sphere { radius 2 } }",
                        "<Shape><Sphere radius='2'/></Shape>",
                        model -> {
                            Mesh mesh = mesh(model, "Sphere");
                            assertThat(mesh.getVertexCount()).isEqualTo(
                                    (Primitives.STACKS + 1) * (Primitives.SLICES + 1));
                            assertThat(((BoundingBox) mesh.getBound()).getYExtent())
                                    .isCloseTo(2f, within(1e-5f));
                        }),
                new Case("Cylinder along Y with its parts",
                        "Shape { geometry Cylinder { radius 0.5 height 3 } }",
                        "<Shape><Cylinder radius='0.5' height='3'/></Shape>",
                        model -> {
                            Mesh mesh = mesh(model, "Cylinder");
                            int slices = Primitives.SLICES;
                            assertThat(mesh.getVertexCount()).isEqualTo(
                                    2 * (slices + 1) + 2 * (slices + 2));
                            BoundingBox box = (BoundingBox) mesh.getBound();
                            assertThat(box.getYExtent()).isCloseTo(1.5f, within(1e-5f));
                            assertThat(box.getXExtent()).isCloseTo(0.5f, within(1e-5f));
                        }),
                new Case("Cylinder without its top",
                        "Shape { geometry Cylinder { top FALSE } }",
                        "<Shape><Cylinder top='false'/></Shape>",
                        model -> assertThat(mesh(model, "Cylinder").getVertexCount()).isEqualTo(
                                2 * (Primitives.SLICES + 1) + Primitives.SLICES + 2)),
                new Case("Cone with VRML's defaults, apex up",
                        "Shape { geometry Cone {} }",
                        "<Shape><Cone/></Shape>",
                        model -> {
                            Mesh mesh = mesh(model, "Cone");
                            assertThat(mesh.getVertexCount()).isEqualTo(
                                    2 * (Primitives.SLICES + 1) + Primitives.SLICES + 2);
                            BoundingBox box = (BoundingBox) mesh.getBound();
                            assertThat(box.getMax(null).y).isCloseTo(1f, within(1e-5f));
                            assertThat(box.getXExtent()).isCloseTo(1f, within(1e-5f));
                        }),
                new Case("Cone without its bottom",
                        "Shape { geometry Cone { bottomRadius 2 height 1 bottom FALSE } }",
                        "<Shape><Cone bottomRadius='2' height='1' bottom='false'/></Shape>",
                        model -> assertThat(mesh(model, "Cone").getTriangleCount())
                                .isEqualTo(Primitives.SLICES)),
                new Case("IndexedFaceSet cube of six quads",
                        "Shape { geometry IndexedFaceSet { coord Coordinate { point [" + CUBE
                                + "] } coordIndex [" + CUBE_FACES + "] } }",
                        "<Shape><IndexedFaceSet coordIndex='" + CUBE_FACES + "'><Coordinate"
                                + " point='" + CUBE + "'/></IndexedFaceSet></Shape>",
                        model -> {
                            Mesh mesh = mesh(model, "IndexedFaceSet");
                            assertThat(mesh.getVertexCount()).isEqualTo(24);
                            assertThat(mesh.getTriangleCount()).isEqualTo(12);
                            assertThat(mesh.getBuffer(VertexBuffer.Type.TexCoord)).isNotNull();
                            assertAllTrianglesFaceTheirNormals(mesh);
                        }),
                new Case("IndexedFaceSet computes face normals",
                        "Shape { geometry IndexedFaceSet { coord Coordinate { point ["
                                + SQUARE_POINTS + "] } coordIndex [0 1 2 3] } }",
                        "<Shape><IndexedFaceSet coordIndex='0 1 2 3'><Coordinate point='"
                                + SQUARE_POINTS + "'/></IndexedFaceSet></Shape>",
                        model -> {
                            Mesh mesh = mesh(model, "IndexedFaceSet");
                            assertThat(mesh.getTriangleCount()).isEqualTo(2);
                            assertThat(vector(mesh, VertexBuffer.Type.Normal, 0))
                                    .isEqualTo(Vector3f.UNIT_Y);
                        }),
                new Case("IndexedFaceSet with clockwise faces",
                        "Shape { geometry IndexedFaceSet { ccw FALSE coord Coordinate { point ["
                                + SQUARE_POINTS + "] } coordIndex [0 1 2 3 -1] } }",
                        "<Shape><IndexedFaceSet ccw='false' coordIndex='0 1 2 3 -1'><Coordinate"
                                + " point='" + SQUARE_POINTS + "'/></IndexedFaceSet></Shape>",
                        model -> {
                            Mesh mesh = mesh(model, "IndexedFaceSet");
                            assertThat(vector(mesh, VertexBuffer.Type.Normal, 0))
                                    .isEqualTo(Vector3f.UNIT_Y.negate());
                            assertAllTrianglesFaceTheirNormals(mesh);
                        }),
                new Case("IndexedFaceSet smooths normals within the crease angle",
                        "Shape { geometry IndexedFaceSet { creaseAngle 1.6 coord Coordinate {"
                                + " point [" + RIDGE + "] } coordIndex [" + RIDGE_FACES + "] } }",
                        "<Shape><IndexedFaceSet creaseAngle='1.6' coordIndex='" + RIDGE_FACES
                                + "'><Coordinate point='" + RIDGE + "'/></IndexedFaceSet></Shape>",
                        model -> {
                            Mesh mesh = mesh(model, "IndexedFaceSet");
                            float half = FastMath.sqrt(0.5f);
                            Vector3f shared = new Vector3f(0, 1 + half, -half).normalizeLocal();
                            // Corners 2 and 5 are point 2, on the edge both faces share.
                            assertClose(vector(mesh, VertexBuffer.Type.Normal, 2), shared);
                            assertClose(vector(mesh, VertexBuffer.Type.Normal, 5), shared);
                            // Corner 0 is point 0, on the first face only.
                            assertClose(vector(mesh, VertexBuffer.Type.Normal, 0),
                                    Vector3f.UNIT_Y);
                        }),
                new Case("IndexedFaceSet keeps an edge sharper than the crease angle",
                        "Shape { geometry IndexedFaceSet { creaseAngle 0.5 coord Coordinate {"
                                + " point [" + RIDGE + "] } coordIndex [" + RIDGE_FACES + "] } }",
                        "<Shape><IndexedFaceSet creaseAngle='0.5' coordIndex='" + RIDGE_FACES
                                + "'><Coordinate point='" + RIDGE + "'/></IndexedFaceSet></Shape>",
                        model -> assertClose(vector(mesh(model, "IndexedFaceSet"),
                                VertexBuffer.Type.Normal, 2), Vector3f.UNIT_Y)),
                new Case("IndexedFaceSet with per-face colours",
                        "Shape { geometry IndexedFaceSet { colorPerVertex FALSE color Color {"
                                + " color [1 0 0, 0 0 1] } colorIndex [1 0] coord Coordinate {"
                                + " point [" + SQUARE_POINTS + "] }"
                                + " coordIndex [0 1 2 -1 0 2 3] } }",
                        "<Shape><IndexedFaceSet colorPerVertex='false' colorIndex='1 0'"
                                + " coordIndex='0 1 2 -1 0 2 3'><Color color='1 0 0, 0 0 1'/>"
                                + "<Coordinate point='" + SQUARE_POINTS + "'/></IndexedFaceSet>"
                                + "</Shape>",
                        model -> {
                            Geometry g = (Geometry) TestModels.find(model.root(), "IndexedFaceSet");
                            FloatBuffer colors = (FloatBuffer) g.getMesh()
                                    .getBuffer(VertexBuffer.Type.Color).getData();
                            assertThat(colors.get(2)).isEqualTo(1f);
                            assertThat(colors.get(4 * 3)).isEqualTo(1f);
                            assertThat((Boolean) g.getMaterial().getParamValue("VertexColor"))
                                    .isTrue();
                        }),
                new Case("IndexedFaceSet with per-vertex colours on a lit shape",
                        "Shape { appearance Appearance { material Material {} } geometry"
                                + " IndexedFaceSet { color Color { color [1 0 0, 0 1 0, 0 0 1,"
                                + " 1 1 1] } coord Coordinate { point [" + SQUARE_POINTS + "] }"
                                + " coordIndex [0 1 2 3] } }",
                        "<Shape><Appearance><Material/></Appearance><IndexedFaceSet"
                                + " coordIndex='0 1 2 3'><Color color='1 0 0, 0 1 0, 0 0 1,"
                                + " 1 1 1'/><Coordinate point='" + SQUARE_POINTS + "'/>"
                                + "</IndexedFaceSet></Shape>",
                        model -> {
                            Geometry g = (Geometry) TestModels.find(model.root(), "IndexedFaceSet");
                            FloatBuffer colors = (FloatBuffer) g.getMesh()
                                    .getBuffer(VertexBuffer.Type.Color).getData();
                            assertThat(new float[] {colors.get(4), colors.get(5), colors.get(6),
                                colors.get(7)}).containsExactly(0f, 1f, 0f, 1f);
                            assertThat((Boolean) g.getMaterial().getParamValue("UseVertexColor"))
                                    .isTrue();
                            assertColor(g.getMaterial(), "Diffuse", ColorRGBA.White);
                        }),
                new Case("IndexedFaceSet with given normals and texture coordinates",
                        "Shape { geometry IndexedFaceSet { coord Coordinate { point ["
                                + SQUARE_POINTS + "] } coordIndex [0 1 2 3] normal Normal {"
                                + " vector [0 0 1] } normalIndex [0 0 0 0] texCoord"
                                + " TextureCoordinate { point [0 0, 0.5 0.5] } texCoordIndex"
                                + " [0 1 1 0] solid FALSE } }",
                        "<Shape><IndexedFaceSet coordIndex='0 1 2 3' normalIndex='0 0 0 0'"
                                + " texCoordIndex='0 1 1 0' solid='false'><Coordinate point='"
                                + SQUARE_POINTS + "'/><Normal vector='0 0 1'/><TextureCoordinate"
                                + " point='0 0, 0.5 0.5'/></IndexedFaceSet></Shape>",
                        model -> {
                            Geometry g = (Geometry) TestModels.find(model.root(), "IndexedFaceSet");
                            assertThat(vector(g.getMesh(), VertexBuffer.Type.Normal, 2))
                                    .isEqualTo(Vector3f.UNIT_Z);
                            FloatBuffer uv = (FloatBuffer) g.getMesh()
                                    .getBuffer(VertexBuffer.Type.TexCoord).getData();
                            assertThat(uv.get(2)).isEqualTo(0.5f);
                            assertThat(g.getMaterial().getAdditionalRenderState()
                                    .getFaceCullMode()).isEqualTo(FaceCullMode.Off);
                        }),
                new Case("IndexedLineSet polyline",
                        "Shape { appearance Appearance { material Material { emissiveColor 1 1 0"
                                + " } } geometry IndexedLineSet { coord Coordinate { point ["
                                + SQUARE_POINTS + "] } coordIndex [0 1 2 3 -1] } }",
                        "<Shape><Appearance><Material emissiveColor='1 1 0'/></Appearance>"
                                + "<IndexedLineSet coordIndex='0 1 2 3 -1'><Coordinate point='"
                                + SQUARE_POINTS + "'/></IndexedLineSet></Shape>",
                        model -> {
                            Geometry g = (Geometry) TestModels.find(model.root(), "IndexedLineSet");
                            assertThat(g.getMesh().getMode()).isEqualTo(Mesh.Mode.Lines);
                            assertThat(g.getMesh().getVertexCount()).isEqualTo(4);
                            assertThat(g.getMesh().getTriangleCount()).isEqualTo(3);
                            assertThat(g.getMaterial().getMaterialDef().getAssetName())
                                    .isEqualTo(LiveMaterial.UNSHADED);
                            assertColor(g.getMaterial(), "Color", ColorRGBA.Yellow);
                        }),
                new Case("DEF and USE share a node",
                        "DEF Left Group { children DEF Leg Transform { translation 0 -1 0"
                                + " children Shape { geometry Box {} } } }"
                                + " DEF Right Group { children USE Leg }",
                        "<Group DEF='Left'><Transform DEF='Leg' translation='0 -1 0'><Shape><Box/>"
                                + "</Shape></Transform></Group><Group DEF='Right'>"
                                + "<Transform USE='Leg'/></Group>",
                        model -> {
                            Node left = (Node) TestModels.find(model.root(), "Left");
                            Node right = (Node) TestModels.find(model.root(), "Right");
                            Spatial leftLeg = left.getChild("Leg");
                            Spatial rightLeg = right.getChild("Leg");
                            assertThat(leftLeg).isNotSameAs(rightLeg);
                            assertThat(TestModels.geometries(leftLeg).get(0).getMesh())
                                    .isSameAs(TestModels.geometries(rightLeg).get(0).getMesh());
                            model.setJointRotation("Leg", Vector3f.UNIT_X, FastMath.PI);
                            assertRotation(rightLeg, Vector3f.UNIT_X, FastMath.PI);
                            assertRotation(leftLeg, Vector3f.UNIT_X, FastMath.PI);
                        }),
                new Case("Switch shows only its chosen child",
                        "DEF Pick Switch { whichChoice 1 choice [ Shape { geometry Box {} }"
                                + " Shape { geometry Sphere {} } ] }",
                        "<Switch DEF='Pick' whichChoice='1'><Shape><Box/></Shape><Shape><Sphere/>"
                                + "</Shape></Switch>",
                        model -> assertThat(((Node) TestModels.find(model.root(), "Pick"))
                                .getChildren()).extracting(Spatial::getName)
                                .containsExactly("Sphere")),
                new Case("Unsupported node types are skipped",
                        "Viewpoint { position 0 1 10 } NavigationInfo { type [\"EXAMINE\"] }"
                                + " DEF Body Group { children [ DirectionalLight { direction 0 -1 0"
                                + " } Shape { geometry Box {} } ] }",
                        "<Viewpoint position='0 1 10'/><NavigationInfo type='\"EXAMINE\"'/>"
                                + "<Group DEF='Body'><DirectionalLight direction='0 -1 0'/>"
                                + "<Shape><Box/></Shape></Group>",
                        model -> assertThat(((Node) TestModels.find(model.root(), "Body"))
                                .getChildren()).extracting(Spatial::getName)
                                .containsExactly("Box")));
    }

    static final String CUBE = "-1 -1 1, 1 -1 1, 1 1 1, -1 1 1, -1 -1 -1, 1 -1 -1, 1 1 -1,"
            + " -1 1 -1";
    static final String CUBE_FACES = "0 1 2 3 -1 5 4 7 6 -1 1 5 6 2 -1 4 0 3 7 -1 3 2 6 7 -1"
            + " 4 5 1 0 -1";
    /** Two faces meeting at 45 degrees along the edge from point 1 to point 2. */
    static final String RIDGE = "0 0 0, 0 0 -1, 1 0 -1, 1 0 0, 0 -1 -2, 1 -1 -2";
    static final String RIDGE_FACES = "0 3 2 1 -1 1 2 5 4 -1";

    static Stream<Arguments> nodeKinds() {
        return cases().stream().flatMap(c -> Stream.of(
                Arguments.of(c.name(), ModelFormat.VRML97, TestModels.vrml(c.vrml()), c.check()),
                Arguments.of(c.name(), ModelFormat.X3D, TestModels.x3d(c.x3d()), c.check())));
    }

    @ParameterizedTest(name = "{0} ({1})")
    @MethodSource("nodeKinds")
    void nodeIsBuiltIntoTheSceneGraph(String name, ModelFormat format, byte[] bytes, Check check)
            throws Exception {
        check.verify(TestModels.load("Guppy", format, bytes));
    }

    static Mesh mesh(BodyModel model, String geometryName) {
        return ((Geometry) TestModels.find(model.root(), geometryName)).getMesh();
    }

    static Vector3f vector(Mesh mesh, VertexBuffer.Type type, int vertex) {
        FloatBuffer data = (FloatBuffer) mesh.getBuffer(type).getData();
        return new Vector3f(data.get(3 * vertex), data.get(3 * vertex + 1),
                data.get(3 * vertex + 2));
    }

    static void assertColor(Material material, String param, ColorRGBA expected) {
        ColorRGBA actual = (ColorRGBA) material.getParamValue(param);
        assertThat(actual.r).as(param + ".r").isCloseTo(expected.r, within(1e-5f));
        assertThat(actual.g).as(param + ".g").isCloseTo(expected.g, within(1e-5f));
        assertThat(actual.b).as(param + ".b").isCloseTo(expected.b, within(1e-5f));
        assertThat(actual.a).as(param + ".a").isCloseTo(expected.a, within(1e-5f));
    }

    static void assertRotation(Spatial spatial, Vector3f axis, float angle) {
        Quaternion expected = new Quaternion().fromAngleAxis(angle, axis);
        assertThat(spatial.getLocalRotation().isSimilar(expected, 1e-4f))
                .as(spatial.getLocalRotation() + " is " + expected).isTrue();
    }

    static void assertClose(Vector3f actual, Vector3f expected) {
        assertThat(actual.distance(expected)).as(actual + " is " + expected)
                .isCloseTo(0f, within(1e-4f));
    }

    /** Every triangle, wound counter-clockwise, faces the way its first vertex's normal does. */
    static void assertAllTrianglesFaceTheirNormals(Mesh mesh) {
        var indices = mesh.getIndexBuffer();
        for (int t = 0; t < mesh.getTriangleCount(); t++) {
            int a = indices.get(3 * t);
            Vector3f pa = vector(mesh, VertexBuffer.Type.Position, a);
            Vector3f pb = vector(mesh, VertexBuffer.Type.Position, indices.get(3 * t + 1));
            Vector3f pc = vector(mesh, VertexBuffer.Type.Position, indices.get(3 * t + 2));
            Vector3f face = pb.subtract(pa).crossLocal(pc.subtract(pa));
            assertThat(face.dot(vector(mesh, VertexBuffer.Type.Normal, a)))
                    .as("triangle " + t).isPositive();
        }
    }

}
